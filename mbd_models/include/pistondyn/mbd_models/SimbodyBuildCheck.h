#pragma once
/// \file
/// Include this (directly or through any pistondyn header that includes Simbody)
/// before Simbody's own headers are used. Debian's libsimbody 3.7 is built WITHOUT
/// NDEBUG and several Simbody classes change their memory layout with NDEBUG
/// (SimTKcommon/internal/StateImpl.h); a translation unit that includes Simbody and is
/// compiled with -DNDEBUG crashes inside realizeTopology() of any model with
/// constraints or motions (docs/DESIGN.md §5). The pistondyn CMake targets add
/// -UNDEBUG to every consumer; this guard stops a build that defeats that.
#if defined(NDEBUG) && !defined(PISTONDYN_SIMBODY_BUILT_WITH_NDEBUG)
#error \
    "pistondyn: a translation unit including Simbody is compiled with NDEBUG, but the \
Simbody it links (Debian libsimbody 3.7) was built without it. Remove -DNDEBUG (pistondyn's \
CMake targets add -UNDEBUG), or define PISTONDYN_SIMBODY_BUILT_WITH_NDEBUG if your Simbody \
really was built with NDEBUG."
#endif

namespace pistondyn::mbd {
/// True if the pistondyn Simbody-facing libraries themselves were compiled with NDEBUG
/// (checked by a test; must be false with Debian's Simbody).
bool libraryBuiltWithNDEBUG();
}  // namespace pistondyn::mbd
