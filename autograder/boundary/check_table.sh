#!/usr/bin/env bash
# ctest contract:boundary-table: every task of tasks/ (each TODO(PnTm) tag)
# has a row in the boundary's table (tasks.def), whose task column names it,
# in the part the tag's file is of; a row of a task that no file of tasks/
# tags is named too. Without its row a task's function is not carried to the
# worker: its graded tests would fail for every submission.
# Usage: check_table.sh TASKS_DIR TASKS_DEF
set -uo pipefail
shopt -s nullglob
tasks_dir=$1 table=$2
failures=0
fail() { echo "$1"; failures=$((failures + 1)); }

# "part task" for each task named by a row (a task column may name several).
rows=$(sed -n 's/^[[:space:]]*PT_\(METHOD\|FUNCTION\)([[:space:]]*\([0-9]\+\)[[:space:]]*,\([^,]*\),.*/\2 \3/p' "$table" |
       while read -r part names; do for t in $names; do echo "$part $t"; done; done | sort -u)
[ -n "$rows" ] || fail "$table: no rows (PT_METHOD(part, task, ...) or PT_FUNCTION(part, task, ...))"

tagged=""
for file in "$tasks_dir"/part[0-9]*_*.cpp; do
  name=$(basename "$file")
  part=${name#part}
  part=${part%%_*}
  for task in $(grep -o 'TODO(P[0-9]\+T[0-9]\+)' "$file" | sed 's/TODO(\(.*\))/\1/' | sort -u); do
    tagged+="$part $task"$'\n'
    [ "${task#P}" != "${task#P"$part"T}" ] || fail "$name: TODO($task) in part $part's file"
    grep -qx "$part $task" <<<"$rows" ||
      fail "$name: TODO($task) has no row in $(basename "$table") (a PT_METHOD or PT_FUNCTION row of part $part naming $task)"
  done
done
[ -n "$tagged" ] || fail "$tasks_dir: no TODO(PnTm) tag in any part*_*.cpp"
while read -r part task; do
  [ -n "$task" ] || continue
  grep -qx "$part $task" <<<"$tagged" || fail "$(basename "$table"): a row of $task (part $part), which no TODO($task) in tasks/ tags"
done <<<"$rows"

[ $failures -eq 0 ] && echo "every task of tasks/ has its row in $(basename "$table")"
exit $((failures > 0))
