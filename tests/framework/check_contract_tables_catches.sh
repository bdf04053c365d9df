#!/usr/bin/env bash
# ctest contract:tables-catches — check_contract_tables.sh must fail on a
# planted checkout and name each of its faults; the same checkout mended
# must pass. Built in a scratch folder: a hidden/ folder may not ship.
# Usage: check_contract_tables_catches.sh SCRATCH_DIR
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
t=$1
rm -rf "$t" && mkdir -p "$t/tasks" "$t/tests/part1/hidden" "$t/tests/part2" "$t/skeleton" "$t/handouts"
touch "$t/skeleton/thing.h" "$t/handouts/part1.md"
printf '// TODO(P1T1): a\n// TODO(P1T2): b\n// TODO(P1T3): c\n// TODO(P1T4): d\n' > "$t/tasks/part1_x.cpp"
printf 'GRADED_TEST(Suite, Seen, "P1T1", 1, Visible) {}\nGRADED_TEST_F(Fix, Also, "P1T2", 1, Visible) {}\n' > "$t/tests/part1/test_a.cpp"
printf 'GRADED_TEST(Suite, Secret, "P1T3", 1, Hidden) {}\n' > "$t/tests/part1/hidden/test_h.cpp"
head='| task | clause | stated in | graded by |
|---|---|---|---|'
write() {  # write FILE ROWS...
  local f=$1; shift
  { printf '# Part 1 contract\n\nWords.\n\n%s\n' "$head"; printf '%s\n' "$@"; } > "$f"
}
write "$t/tests/part1/CONTRACT.md" \
  '| P1T1 | x in [0, 1) | `skeleton/thing.h` | `Suite.Seen` |' \
  '| P1T1 | a clause nobody grades | handouts/part1.md §2 | |' \
  '| P1T2 | a name that is no test | handouts/part1.md | `Fix.Gone` |' \
  '| P1T2 | a hidden name in sight | handouts/part1.md | `Suite.Secret` |' \
  '| P1T3 | held by hidden tests | skeleton/missing.h | hidden |' \
  '| P2T1 | another part | handouts/part1.md | `Suite.Seen` |' \
  '| P1T1 | loose words | handouts/part1.md | `Suite.Seen` and the camera tests |'
write "$t/tests/part1/hidden/CONTRACT.md" '| P1T1 | other task | handouts/part1.md | `Suite.Secret` |'
out=$("$here/check_contract_tables.sh" "$t" "1 2")
status=$?
echo "$out"
[ "$status" -ne 0 ] || { echo "the check passed planted tables"; exit 1; }
for expected in "tests/part2/CONTRACT.md: missing" \
                "P1T1: empty 'graded by'" \
                "P1T2: no graded test Fix.Gone in tests/part1" \
                "P1T2: Suite.Secret is a hidden test" \
                "P1T3: 'stated in' names skeleton/missing.h, which does not exist" \
                "task 'P2T1' is not a task of part 1" \
                "task P1T4 (tagged in tasks/) has no row" \
                "P1T1: 'graded by' is backticked Suite.Name entries separated by commas, or the word hidden" \
                "a row of P1T3 is graded 'hidden' and tests/part1/hidden/CONTRACT.md has no row for P1T3"; do
  grep -qF -- "$expected" <<< "$out" || { echo "not caught: $expected"; exit 1; }
done
# Mended, the same checkout passes: the check fails for the faults, not the format.
write "$t/tests/part1/CONTRACT.md" \
  '| P1T1 | x in [0, 1) | `skeleton/thing.h` | `Suite.Seen` |' \
  '| P1T2 | the mean \| its samples | handouts/part1.md §2 | `Fix.Also`, `Suite.Seen` |' \
  '| P1T3 | held by hidden tests | skeleton/thing.h | hidden |' \
  '| P1T4 | named | handouts/part1.md | `Suite.Seen` |'
write "$t/tests/part1/hidden/CONTRACT.md" '| P1T3 | held | handouts/part1.md | `Suite.Secret` |'
write "$t/tests/part2/CONTRACT.md" '| P2T1 | anything | handouts/part1.md | hidden |'
rm -rf "$t/tests/part2/hidden"  # as in the release: no hidden/ to look in
out=$("$here/check_contract_tables.sh" "$t" "1 2") || { echo "$out"; echo "the check failed mended tables"; exit 1; }
echo "$out"
rm -rf "$t"
echo "every planted fault caught; the mended tables pass"
