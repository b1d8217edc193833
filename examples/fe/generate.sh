#!/usr/bin/env bash
# Regenerates the committed compliance files of both example engines (examples/fe/README.md);
# materials from the decks (liner.asperity.*).
# Run from anywhere; writes beside this script. CPU: see the run times in README.md.
set -euo pipefail
cd "$(dirname "$0")"
export OMP_NUM_THREADS=1   # ccx single-threaded: the results do not depend on the thread count
run() { nice -n 10 python3 make_compliance.py "$@"; }

run skirt --deck ../engines/briggs_stratton_500/engine.yaml --out briggs_stratton_500 \
    --n-phi 32 --n-y 17 --refine 2
run liner --deck ../engines/briggs_stratton_500/engine.yaml --out briggs_stratton_500 \
    --n-phi 24 --refine 2
run skirt --deck ../engines/gasoline_1400_2000rpm/engine.yaml --out gasoline_1400_2000rpm \
    --n-phi 24 --n-y 11 --refine 2
run liner --deck ../engines/gasoline_1400_2000rpm/engine.yaml --out gasoline_1400_2000rpm \
    --n-phi 24 --refine 2

# Mesh refinement of the gasoline skirt: diagonal at the thrust (0 deg) and pin (90 deg) lines,
# 3, 4 and 5 elements per structural cell (the committed files have 2; README, run times).
for m in 3 4 5; do
  run skirt --deck ../engines/gasoline_1400_2000rpm/engine.yaml --out refinement \
      --name gasoline_skirt_refine$m --n-phi 24 --n-y 11 --refine $m --diagonal-at-phi-deg 0,90
done

# Verification (tests/io/test_fe_compliance.cpp): the uniform ring load on the bottom row as one
# load case, on the gasoline skirt and on a variant whose pin bosses end at the pin axis.
run skirt --deck ../engines/gasoline_1400_2000rpm/engine.yaml --out verification \
    --name gasoline_skirt --n-phi 24 --n-y 11 --refine 2 --ring-at-row 0
run skirt --deck ../engines/gasoline_1400_2000rpm/engine.yaml --out verification \
    --name gasoline_skirt_short_bosses --n-phi 24 --n-y 11 --refine 2 --boss-half-height-mm 0 \
    --ring-at-row 0
