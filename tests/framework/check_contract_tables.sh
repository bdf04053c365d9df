#!/usr/bin/env bash
# ctest contract:tables — every task's contract is written down clause by
# clause beside its part's tests, and each clause names the graded tests that
# hold it (tests/partN/CONTRACT.md; the clauses only hidden tests hold are in
# tests/partN/hidden/CONTRACT.md, which never ships). It fails when
#  - a required part has no CONTRACT.md, or a table is not the one agreed
#    (a heading, a paragraph, one table headed | task | clause | stated in | graded by |);
#  - a task tagged TODO(PnTm) in tasks/ has no row in its part's tables;
#  - a row's clause, stated-in or graded-by cell is empty, or stated-in names
#    a skeleton/ or handouts/ file that does not exist;
#  - a named test is not a GRADED_TEST, GRADED_TEST_F or GRADED_EXTENSION_TEST
#    of tests/partN (the visible table may name only tests outside hidden/);
#  - a row graded `hidden` has no row for its task in hidden/CONTRACT.md
#    (checked where hidden/ exists: not in the student release).
# Usage: check_contract_tables.sh SOURCE_DIR "REQUIRED PARTS" (e.g. "1 2")
# A part outside REQUIRED PARTS is checked once its CONTRACT.md exists.
set -uo pipefail
shopt -s nullglob
src=$1 required=" $2 "
failures=0
fail() { echo "$1"; failures=$((failures + 1)); }
header='| task | clause | stated in | graded by |'

# Suite.Name of every graded test defined in the given files.
graded_tests() {
  [ $# -gt 0 ] || return 0
  sed -n 's/^[[:space:]]*GRADED_\(TEST\|TEST_F\|EXTENSION_TEST\)([[:space:]]*\([A-Za-z0-9_]*\)[[:space:]]*,[[:space:]]*\([A-Za-z0-9_]*\).*/\2.\3/p' "$@" | sort -u
}
# trim VAR TEXT: VAR = TEXT without leading and trailing blanks (no subshell:
# a fork per cell made the check take seconds).
trim() { local s=$2; s=${s#"${s%%[![:space:]]*}"}; s=${s%"${s##*[![:space:]]}"}; printf -v "$1" '%s' "$s"; }

# check_table FILE PART KIND: the tests a row may name are the keys of
# `allowed`; appends "task<TAB>hidden|named" per row to $rows_file.
check_table() {
  local file=$1 part=$2 kind=$3 rel=${1#"$src"/}
  local state=before tables=0 lineno=0 line
  while IFS= read -r line || [ -n "$line" ]; do
    lineno=$((lineno + 1))
    if [[ $line != \|* ]]; then
      [ $state = rows ] && state=after
      continue
    fi
    case $state in
      before)
        tables=$((tables + 1))
        local head
        trim head "$line"
        [ "$head" = "$header" ] || fail "$rel:$lineno: the table's header must be exactly '$header'"
        state=separator
        continue ;;
      separator)
        [[ $line =~ ^\|([[:space:]]*:?-+:?[[:space:]]*\|){4}[[:space:]]*$ ]] ||
          fail "$rel:$lineno: the header must be followed by the separator row |---|---|---|---|"
        state=rows
        continue ;;
      after)
        tables=$((tables + 1)); state=rows
        fail "$rel:$lineno: one table per file (a second one starts here)" ;;
    esac
    # A row: four cells; an escaped \| belongs to its cell.
    local cells=${line//\\|/$'\x01'}
    cells=${cells#|}; cells=${cells%|*}
    IFS='|' read -r -a cell <<< "$cells"
    if [ ${#cell[@]} -ne 4 ]; then
      fail "$rel:$lineno: a row has 4 cells (task, clause, stated in, graded by), this one ${#cell[@]}"
      continue
    fi
    local task clause stated graded
    trim task "${cell[0]}"; trim clause "${cell[1]}"; trim stated "${cell[2]}"; trim graded "${cell[3]}"
    [[ $task =~ ^P${part}T[0-9]+$ ]] || fail "$rel:$lineno: task '$task' is not a task of part $part (P${part}T1, P${part}T2, ...)"
    [ -n "$clause" ] || fail "$rel:$lineno: $task: empty clause"
    [ -n "$stated" ] || fail "$rel:$lineno: $task: empty 'stated in' (a header path and/or a handout section)"
    local rest=$stated path
    while [[ $rest =~ (skeleton|handouts)/[A-Za-z0-9_./-]*[A-Za-z0-9_] ]]; do
      path=${BASH_REMATCH[0]}
      rest=${rest#*"$path"}
      [ -f "$src/$path" ] || fail "$rel:$lineno: $task: 'stated in' names $path, which does not exist"
    done
    if [ -z "$graded" ]; then
      fail "$rel:$lineno: $task: empty 'graded by' (name the graded tests, or write hidden)"
      continue
    fi
    if [ "$graded" = hidden ]; then
      [ "$kind" = visible ] || fail "$rel:$lineno: $task: the hidden table names its tests"
      printf '%s\thidden\n' "$task" >> "$rows_file"
      continue
    fi
    local name
    rest=$graded
    while [[ $rest =~ ^[[:space:],]*\`([A-Za-z0-9_]+\.[A-Za-z0-9_]+)\`(.*)$ ]]; do
      name=${BASH_REMATCH[1]}
      rest=${BASH_REMATCH[2]}
      if [ -z "${allowed[$name]:-}" ]; then
        if [ "$kind" = visible ] && [ -n "${hidden_set[$name]:-}" ]; then
          fail "$rel:$lineno: $task: $name is a hidden test: name it in hidden/CONTRACT.md and write hidden here"
        else
          fail "$rel:$lineno: $task: no graded test $name in tests/part$part"
        fi
      fi
    done
    [[ $rest =~ ^[[:space:],]*$ ]] ||
      fail "$rel:$lineno: $task: 'graded by' is backticked Suite.Name entries separated by commas, or the word hidden: '$graded'"
    printf '%s\tnamed\n' "$task" >> "$rows_file"
  done < "$file"
  [ $tables -gt 0 ] || fail "$rel: no table headed '$header'"
}

rows_file=$(mktemp)
trap 'rm -f "$rows_file"' EXIT
checked=""
for part in 1 2 3 4 5; do
  dir=$src/tests/part$part
  table=$dir/CONTRACT.md hidden_table=$dir/hidden/CONTRACT.md
  if [ ! -f "$table" ]; then
    [[ $required == *" $part "* ]] && fail "tests/part$part/CONTRACT.md: missing (part $part's contract table)"
    continue
  fi
  checked="$checked $part"
  declare -A allowed=() hidden_set=()
  for name in $(graded_tests "$dir"/*.cpp); do allowed[$name]=1; done
  [ -d "$dir/hidden" ] && for name in $(graded_tests "$dir"/hidden/*.cpp); do hidden_set[$name]=1; done
  : > "$rows_file"
  check_table "$table" $part visible
  rows=$(cat "$rows_file")
  for name in "${!hidden_set[@]}"; do allowed[$name]=1; done
  : > "$rows_file"
  [ -f "$hidden_table" ] && check_table "$hidden_table" $part hidden
  hidden_rows=$(cat "$rows_file")
  unset allowed hidden_set
  task_files=("$src"/tasks/part${part}_*.cpp)
  for task in $([ ${#task_files[@]} -gt 0 ] && cat "${task_files[@]}" | grep -oE "TODO\(P${part}T[0-9]+\)" | sed 's/TODO(\(.*\))/\1/' | sort -u); do
    grep -q "^$task"$'\t' <<< "$rows"$'\n'"$hidden_rows" || fail "tests/part$part/CONTRACT.md: task $task (tagged in tasks/) has no row"
  done
  if [ -d "$dir/hidden" ]; then
    for task in $(grep $'\thidden$' <<< "$rows" | cut -f1 | sort -u); do
      grep -q "^$task"$'\t' <<< "$hidden_rows" ||
        fail "tests/part$part/CONTRACT.md: a row of $task is graded 'hidden' and tests/part$part/hidden/CONTRACT.md has no row for $task"
    done
  fi
done
if [ $failures -gt 0 ]; then
  echo "contract tables: $failures problem(s) (format: tests/framework/check_contract_tables.sh)"
  exit 1
fi
echo "contract tables: parts${checked:- none} checked, every tagged task has its rows and every named test exists"
