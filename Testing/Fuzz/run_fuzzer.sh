#!/usr/bin/env bash
# Runs one fuzz target over every seed (the past findings among them) and then for a
# bounded time on a scratch copy of the seed corpus, so the repository is not modified.
# A crash leaves its input in the work folder and fails the test.
# Usage: run_fuzzer.sh TARGET SEED_DIR WORK_DIR SECONDS
set -euo pipefail
target="$1" seeds="$2" work="$3" seconds="$4"
rm -rf "${work}"
mkdir -p "${work}/corpus" "${work}/findings"
cp -r "${seeds}/." "${work}/corpus/"
cd "${work}"
"${target}" -max_total_time="${seconds}" -timeout=20 -rss_limit_mb=4096 -malloc_limit_mb=4096 \
  -artifact_prefix=findings/ -print_final_stats=1 corpus
