#!/usr/bin/env bash
# README command (b): install dependencies, build, run the whole test suite (CTest +
# GoogleTest). .ci/run runs exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
# Labels outside the default run: bench (whole-cycle timings), slow (FE regeneration),
# docs (the API reference: `ctest --test-dir build -L docs`).
ctest --test-dir build --output-on-failure -j"$(nproc)" -LE "bench|slow|docs"
