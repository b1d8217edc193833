#pragma once
/// \file
/// A skirt side's history (SkirtSideHistory) as a flat list of numbers and back: what a warm
/// start carries from the end of one run to the start of the next (plugin::WarmStart).
///
/// The record holds the mass-conserving film's last and earlier points (fill fraction, expected
/// gap) and the step between them, the liner oil per cell and the pin height it belongs to, the
/// elastic skirt's gap term, structural displacement and rate. Layout: each of these ten arrays
/// as its length followed by its values, in the order of SkirtSideHistory's members (the step
/// and the pin height as arrays of one value, or none).

#include <cstddef>
#include <vector>

#include "pistondyn/skirt/SkirtSideSolver.h"

namespace pistondyn::skirt {

/// Appends the side's record to `out`.
void appendSkirtSideRecord(const SkirtSideHistory& history, std::vector<double>& out);

/// Reads one side's record from `record` at `offset` (advanced past it) for a side of
/// `filmNodes` film nodes. Throws std::invalid_argument when the record is cut short, an
/// array length is not a whole non-negative number, a film array is neither empty nor one
/// value per node, a value is not finite, a fill fraction is outside [0, 1], a gap or liner
/// oil volume is negative.
SkirtSideHistory readSkirtSideRecord(const std::vector<double>& record, std::size_t& offset,
                                     std::size_t filmNodes);

}  // namespace pistondyn::skirt
