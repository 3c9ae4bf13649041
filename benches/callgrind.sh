#!/bin/sh
# Instruction counts per call of every generated function, its hand form and
# the interpreter (benches/tools/instr_count.rs) under valgrind's callgrind.
# Usage: benches/callgrind.sh [DIR]   (default target/callgrind)
set -eu
dir=${1:-target/callgrind}
rm -rf "$dir" && mkdir -p "$dir"
cargo build --release -p pegdyn-benches --bin instr_count
valgrind --tool=callgrind --callgrind-out-file="$dir/cg.out" \
    --dump-before='*callgrind_region*' \
    target/release/instr_count run > "$dir/order.txt" 2> "$dir/valgrind.log"
target/release/instr_count report "$dir"
