#!/usr/bin/env bash
# Mutation testing of the core's formula files (issue 30): cargo-mutants changes one operator, constant or function
# body at a time in src/ (not the JavaScript bindings in src/api, not the error texts) and runs the native tests;
# a mutant that every test survives is a formula no test checks. Too slow for CI (every mutant is a rebuild and a
# test run: hours on 2 cores for the full set), so it runs in shards that can be run apart and at different times.
#
#   scripts/mutants.sh --list                 the mutants of the full formula set, one per line (no build)
#   scripts/mutants.sh --shard 0/8            runs one eighth of them (k/n, k from 0); results in mutants.out/
#   scripts/mutants.sh --shard 0/8 -- …       extra arguments after -- go to cargo-mutants
#
# Score = caught / (caught + missed), over viable mutants (those that build and whose unmutated tests pass in time);
# record it, with every missed mutant and the test that now kills it or why it is equivalent, in tests/ROBUSTNESS.md.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v cargo-mutants >/dev/null || { echo "cargo-mutants is missing: cargo install cargo-mutants" >&2; exit 2; }

# the formula files: every core module, without the bindings (src/api), the crate root and the error texts
mapfile -t FILES < <(find src -name '*.rs' -not -path 'src/api/*' -not -name lib.rs -not -name error.rs | sort)
ARGS=()
for f in "${FILES[@]}"; do ARGS+=(--file "$f"); done

case "${1:-}" in
  --list) exec cargo mutants --list "${ARGS[@]}" ;;
  --shard)
    [[ -n "${2:-}" ]] || { echo "usage: scripts/mutants.sh --shard k/n [-- extra cargo-mutants args]" >&2; exit 2; }
    SHARD=$2; shift 2; [[ "${1:-}" == "--" ]] && shift
    # native tests only (the wasm layers test the bindings, not the formulas); --no-shuffle keeps shards stable
    OUT=mutants.out/"${SHARD/\//-of-}"; mkdir -p "$OUT"   # cargo-mutants writes $OUT/mutants.out/{caught,missed,…}.txt
    exec cargo mutants "${ARGS[@]}" --shard "$SHARD" --no-shuffle --timeout-multiplier 3 --output "$OUT" "$@" ;;
  *) echo "usage: scripts/mutants.sh --list | --shard k/n [-- extra cargo-mutants args]" >&2; exit 2 ;;
esac
