#pragma once
// Checks of the per-call inputs and preallocated outputs (private header): cheap, allocation
// free unless they throw.

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "Checks.h"
#include "pistondyn/skirt/PistonPose.h"

namespace pistondyn::skirt::detail {

inline void requireNodalSize(const char* fn, const char* name, Eigen::Index size,
                             Eigen::Index nodes) {
  if (size != nodes)
    fail(fn, std::string(name) + " has " + std::to_string(size) + " entries, expected " +
                 std::to_string(nodes) + " (one per grid node)");
}

inline void requireNodalMatrix(const char* fn, const char* name, Eigen::Index rows,
                               Eigen::Index cols, Eigen::Index nodes) {
  if (rows != nodes || cols != 3)
    fail(fn, std::string(name) + " is " + std::to_string(rows) + " x " + std::to_string(cols) +
                 ", expected " + std::to_string(nodes) + " x 3 (nodes x lateral, tilt, tertiary)");
}

inline void requirePose(const char* fn, const PistonPose& pose, const PistonPoseRate& rate) {
  requireFinite(fn, "pose.lateral_m", pose.lateral_m, "m");
  requireFinite(fn, "pose.tilt_rad", pose.tilt_rad, "rad");
  requireFinite(fn, "pose.tertiary_m", pose.tertiary_m, "m");
  requireFinite(fn, "rate.lateral_mps", rate.lateral_mps, "m/s");
  requireFinite(fn, "rate.tilt_radps", rate.tilt_radps, "rad/s");
  requireFinite(fn, "rate.tertiary_mps", rate.tertiary_mps, "m/s");
}

}  // namespace pistondyn::skirt::detail
