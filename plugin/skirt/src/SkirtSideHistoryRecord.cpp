#include "pistondyn/skirt/SkirtSideHistoryRecord.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pistondyn::skirt {
namespace {

template <class Array>
void append(const Array& a, std::vector<double>& out) {
  out.push_back(static_cast<double>(a.size()));
  out.insert(out.end(), a.data(), a.data() + a.size());
}

// A value that is there or not: an array of one value, or of none.
void appendOptional(bool present, double value, std::vector<double>& out) {
  out.push_back(present ? 1.0 : 0.0);
  if (present)
    out.push_back(value);
}

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("skirt side record: " + what);
}

// One array: its length (with perNode: none or one value per film node), then its values.
template <class Array>
Array read(const std::vector<double>& record, std::size_t& offset, const char* name,
           std::size_t filmNodes, bool perNode) {
  if (offset >= record.size())
    fail(std::string("cut short before ") + name);
  const double n = record[offset++];
  if (!(n >= 0.0) || n != std::floor(n) || n > static_cast<double>(record.size() - offset))
    fail(std::string(name) + ": the length is not a whole number within the record");
  const auto size = static_cast<std::size_t>(n);
  if (perNode && size != 0 && size != filmNodes) {
    fail(std::string(name) + " has " + std::to_string(size) + " values where the side has " +
         std::to_string(filmNodes) + " film nodes (another grid?)");
  }
  Array a(static_cast<Eigen::Index>(size));
  for (std::size_t i = 0; i < size; ++i) {
    const double v = record[offset + i];
    if (!std::isfinite(v))
      fail(std::string(name) + " holds a value that is not finite");
    a[static_cast<Eigen::Index>(i)] = v;
  }
  offset += size;
  return a;
}

// One film point: its fill fraction and expected gap.
lubrication::FilmHistoryPoint readFilmPoint(const std::vector<double>& record,
                                            std::size_t& offset, std::size_t filmNodes) {
  lubrication::FilmHistoryPoint p;
  p.fillFraction = read<Eigen::ArrayXd>(record, offset, "fill fraction", filmNodes, true);
  p.expectedGap_m = read<Eigen::ArrayXd>(record, offset, "expected gap", filmNodes, true);
  if ((p.fillFraction < 0.0).any() || (p.fillFraction > 1.0).any())
    fail("a fill fraction is outside [0, 1]");
  if ((p.expectedGap_m <= 0.0).any())
    fail("an expected gap is not positive");
  if (p.expectedGap_m.size() != 0 && p.fillFraction.size() == 0)
    fail("an expected gap needs the fill fraction of its point");
  return p;
}

}  // namespace

void appendSkirtSideRecord(const SkirtSideHistory& h, std::vector<double>& out) {
  append(h.film.last.fillFraction, out);
  append(h.film.last.expectedGap_m, out);
  append(h.film.earlier.fillFraction, out);
  append(h.film.earlier.expectedGap_m, out);
  appendOptional(!h.film.earlier.empty(), h.film.earlierStep_s, out);
  append(h.liner.volume_m3, out);
  appendOptional(!h.liner.empty(), h.liner.pinHeight_m, out);
  append(h.elastic.gapTerm_m, out);
  append(h.elastic.structural_m, out);
  append(h.elastic.structuralRate_mps, out);
}

SkirtSideHistory readSkirtSideRecord(const std::vector<double>& record, std::size_t& offset,
                                     std::size_t filmNodes) {
  SkirtSideHistory h;
  h.film.last = readFilmPoint(record, offset, filmNodes);
  h.film.earlier = readFilmPoint(record, offset, filmNodes);
  const Eigen::ArrayXd step = read<Eigen::ArrayXd>(record, offset, "film step", filmNodes, false);
  if (step.size() != (h.film.earlier.empty() ? 0 : 1))
    fail("the film's earlier point needs the one step to it");
  if (step.size() == 1) {
    if (!(step[0] > 0.0))
      fail("the film's step is not positive");
    if (h.film.last.empty())
      fail("the film's earlier point needs its last point");
    h.film.earlierStep_s = step[0];
  }
  h.liner.volume_m3 = read<Eigen::ArrayXd>(record, offset, "liner oil volume", filmNodes, false);
  if ((h.liner.volume_m3 < 0.0).any())
    fail("a liner oil volume is negative");
  const Eigen::ArrayXd pin = read<Eigen::ArrayXd>(record, offset, "pin height", filmNodes, false);
  if (pin.size() != (h.liner.empty() ? 0 : 1))
    fail("the liner oil needs the one pin height it belongs to");
  if (pin.size() == 1)
    h.liner.pinHeight_m = pin[0];
  auto& e = h.elastic;
  e.gapTerm_m = read<Eigen::ArrayXd>(record, offset, "elastic gap term", filmNodes, true);
  e.structural_m = read<Eigen::VectorXd>(record, offset, "structural displacement", filmNodes,
                                         false);
  e.structuralRate_mps =
      read<Eigen::VectorXd>(record, offset, "structural rate", filmNodes, false);
  return h;
}

}  // namespace pistondyn::skirt
