#pragma once
/// \file
/// The comparison table of a study (a sweep deck with a few cases, `pistondyn study`): one
/// row per case with its overrides and the figures a piston designer compares, written as
///
///   comparison.csv   '#' comment lines (program, study, base deck, conventions), a header,
///                    one row per case; numbers as summary.json has them (the shortest text
///                    that reads back to the same double); empty where a case lacks one
///   comparison.md    the same as a Markdown table with units in the headers, numbers to 4
///                    significant digits, each minimum h/σ with its crank angle
///
/// The figures come from each case's summary.json (`results`): kComparisonFigures below.
/// A failed case has status `failed`, its message and no figures.

#include <string>
#include <vector>

#include "pistondyn/io/SweepDeck.h"
#include "pistondyn/io/SweepRun.h"

namespace pistondyn::io {

/// summary.json result keys the table holds, in its column order (units in the names).
extern const std::vector<std::string> kComparisonFigures;

/// One case's row of a study's comparison table.
struct StudyComparisonRow {
  int index = 0;                     ///< the case (1-based)
  std::string folder;                ///< its run folder in the sweep's folder ("case_0001")
  std::vector<std::string> values;   ///< the case's value of each swept key ("" if not set)
  bool ok = false;                   ///< the case ran and wrote its results
  std::string message;               ///< why it failed
  std::vector<std::string> figures;  ///< JSON text of each kComparisonFigures entry, "" if absent
};

/// A study's comparison table: one row per case, the swept keys and the figures.
struct StudyComparison {
  std::string name;                      ///< the study's label (sweep deck `name`), may be empty
  std::string studyDeckPath;             ///< as given
  std::string baseDeckPath;              ///< absolute
  std::vector<std::string> sweptKeys;    ///< the swept keys, in deck order
  std::vector<StudyComparisonRow> rows;  ///< by case index
};

/// The table of `plan`'s cases from their results (any order; a case without a result is
/// reported as failed, "not run"). Throws std::runtime_error if an ok result's summary.json
/// cannot be parsed.
StudyComparison makeStudyComparison(const SweepPlan& plan,
                                    const std::vector<SweepCaseResult>& results);

/// The text of comparison.csv: '#' lines, header, one row per case.
std::string makeComparisonCsv(const StudyComparison& comparison);
/// The text of comparison.md: a Markdown table, units in the headers, 4 significant digits.
std::string makeComparisonMarkdown(const StudyComparison& comparison);

/// The legend of a case in figures: its overrides as `key=value`, each key shortened to its
/// last part when that is unique among the swept keys ("film_um=0.5"); "case N" if it has none.
std::string describeCase(const StudyComparison& comparison, const StudyComparisonRow& row);

}  // namespace pistondyn::io
