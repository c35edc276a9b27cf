#!/bin/sh
# run_fuzz.sh <fuzz binary> <seed corpus folder> <seconds> <work folder>
# One bounded libFuzzer run (the CTest fuzz_<target>): a fresh corpus in <work>/corpus grows from
# the committed seeds (left untouched), crash inputs land in <work>/ as crash-*, leak-*, oom-*;
# a finding makes libFuzzer exit non-zero, and the test fails. Seeds stay under 4 KiB.
set -eu
binary=$1 seeds=$2 seconds=$3 work=$4
rm -rf "$work/corpus"
mkdir -p "$work/corpus"
exec "$binary" -max_total_time="$seconds" -max_len=4096 -rss_limit_mb=2048 -timeout=10 \
  -artifact_prefix="$work/" -print_final_stats=1 "$work/corpus" "$seeds"
