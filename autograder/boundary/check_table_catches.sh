#!/usr/bin/env bash
# ctest contract:boundary-table-catches: check_table.sh fails on a table with
# a task's row taken out (the first row of Part 1, planted in a copy), and on
# a tasks/ file whose TODO names a task with no row; it passes on the copies
# left as they are.
# Usage: check_table_catches.sh TASKS_DIR TASKS_DEF WORK_DIR
set -uo pipefail
tasks_dir=$1 table=$2 work=$3
check=$(dirname "$0")/check_table.sh
rm -rf "$work" && mkdir -p "$work/tasks" && cp "$tasks_dir"/part*_*.cpp "$work/tasks/" && cp "$table" "$work/tasks.def"
"$check" "$work/tasks" "$work/tasks.def" >/dev/null || { echo "the untouched copies fail the check"; exit 1; }

# A row missing: P1T1's (its first line is all the check reads of it).
grep -v '^PT_METHOD(1, P1T1,' "$table" >"$work/missing.def"
out=$("$check" "$work/tasks" "$work/missing.def")
[ $? -ne 0 ] && grep -q 'TODO(P1T1) has no row' <<<"$out" || { echo "a table without P1T1's row passed: $out"; exit 1; }

# A task tagged that no row names.
printf '\n// TODO(P1T9): a task added to tasks/ without its row\n' >>"$work/tasks/part1_raygen_intersect.cpp"
out=$("$check" "$work/tasks" "$work/tasks.def")
[ $? -ne 0 ] && grep -q 'TODO(P1T9) has no row' <<<"$out" || { echo "a TODO(P1T9) without a row passed: $out"; exit 1; }
echo "check_table.sh fails on a missing row and on a task without one"
