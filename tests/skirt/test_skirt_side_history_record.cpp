// A skirt side's history as a warm-start record (SkirtSideHistoryRecord.h): what is written
// reads back to the identical arrays, and a record that does not fit the side is refused with
// a message that says why (the reference: the record's own layout, stated in the header).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "pistondyn/skirt/SkirtSideHistoryRecord.h"

namespace {

using pistondyn::skirt::appendSkirtSideRecord;
using pistondyn::skirt::readSkirtSideRecord;
using pistondyn::skirt::SkirtSideHistory;

SkirtSideHistory filledHistory(int nodes) {
  SkirtSideHistory h;
  h.film.last.fillFraction = Eigen::ArrayXd::LinSpaced(nodes, 0.1, 1.0);
  h.film.last.expectedGap_m = Eigen::ArrayXd::LinSpaced(nodes, 1e-6, 3e-5);
  h.film.earlier.fillFraction = Eigen::ArrayXd::LinSpaced(nodes, 0.2, 0.9);
  h.film.earlier.expectedGap_m = Eigen::ArrayXd::LinSpaced(nodes, 2e-6, 2e-5);
  h.film.earlierStep_s = 1e-5;
  h.liner.volume_m3 = Eigen::ArrayXd::LinSpaced(7, 0.0, 1e-9);
  h.liner.pinHeight_m = 0.123;
  h.elastic.gapTerm_m = Eigen::ArrayXd::Constant(nodes, -2e-6);
  h.elastic.structural_m = Eigen::VectorXd::LinSpaced(5, -1e-5, 1e-5);
  h.elastic.structuralRate_mps = Eigen::VectorXd::Constant(5, 0.25);
  return h;
}

std::string messageOf(const std::vector<double>& record, std::size_t nodes) {
  std::size_t offset = 0;
  try {
    readSkirtSideRecord(record, offset, nodes);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SkirtSideHistoryRecord, TwoSidesReadBackToTheIdenticalStateAtOneInstant) {
  const SkirtSideHistory a = filledHistory(12), b;  // b: a full film at rest (all empty)
  std::vector<double> record;
  appendSkirtSideRecord(a, record);
  appendSkirtSideRecord(b, record);
  std::size_t offset = 0;
  const SkirtSideHistory ra = readSkirtSideRecord(record, offset, 12);
  const SkirtSideHistory rb = readSkirtSideRecord(record, offset, 12);
  EXPECT_EQ(offset, record.size());
  EXPECT_TRUE((ra.film.last.fillFraction == a.film.last.fillFraction).all());
  EXPECT_TRUE((ra.film.last.expectedGap_m == a.film.last.expectedGap_m).all());
  EXPECT_TRUE((ra.film.earlier.fillFraction == a.film.earlier.fillFraction).all());
  EXPECT_TRUE((ra.film.earlier.expectedGap_m == a.film.earlier.expectedGap_m).all());
  EXPECT_EQ(ra.film.earlierStep_s, a.film.earlierStep_s);
  EXPECT_TRUE((ra.liner.volume_m3 == a.liner.volume_m3).all());
  EXPECT_EQ(ra.liner.pinHeight_m, a.liner.pinHeight_m);
  EXPECT_TRUE((ra.elastic.gapTerm_m == a.elastic.gapTerm_m).all());
  EXPECT_EQ(ra.elastic.structural_m, a.elastic.structural_m);
  EXPECT_EQ(ra.elastic.structuralRate_mps, a.elastic.structuralRate_mps);
  EXPECT_TRUE(rb.film.empty());
  EXPECT_TRUE(rb.liner.empty());
  EXPECT_EQ(rb.elastic.gapTerm_m.size(), 0);
}

TEST(SkirtSideHistoryRecord, ARecordThatDoesNotFitTheSideIsRefusedWithItsReason) {
  std::vector<double> record;
  appendSkirtSideRecord(filledHistory(12), record);
  EXPECT_NE(messageOf(record, 20).find("12 values where the side has 20 film nodes"),
            std::string::npos)
      << messageOf(record, 20);
  std::vector<double> shortRecord(record.begin(), record.begin() + 5);
  EXPECT_NE(messageOf(shortRecord, 12).find("not a whole number within the record"),
            std::string::npos);
  std::vector<double> overfull = record;
  overfull[1] = 1.5;  // the first fill fraction
  EXPECT_NE(messageOf(overfull, 12).find("outside [0, 1]"), std::string::npos);
  std::vector<double> fractional = record;
  fractional[0] = 11.5;  // the first length
  EXPECT_NE(messageOf(fractional, 12).find("not a whole number"), std::string::npos);
  std::vector<double> nan = record;
  nan[14] = std::nan("");  // an expected gap
  EXPECT_NE(messageOf(nan, 12).find("not finite"), std::string::npos);
  EXPECT_NE(messageOf({}, 12).find("cut short"), std::string::npos);
  std::vector<double> backwards = record;
  ASSERT_EQ(record[4 * 13], 1.0);   // after four arrays of 1 + 12 numbers: the step's length
  backwards[4 * 13 + 1] = -1e-5;     // the step between the film's points
  EXPECT_NE(messageOf(backwards, 12).find("step is not positive"), std::string::npos)
      << messageOf(backwards, 12);
}

}  // namespace
