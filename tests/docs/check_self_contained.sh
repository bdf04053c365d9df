#!/usr/bin/env bash
# ctest docs:self-contained — the repository cites nothing a reader of it cannot
# open: no section of a design document kept elsewhere ("DESIGN section 3",
# "DESIGN.md"), no issue of a tracker ("issue 17"). The design of record is
# docs/architecture.md; a reason belongs in the comment or the commit message,
# not behind a number.
# Usage: check_self_contained.sh SOURCE_DIR [FILE...]   (default: every file
# git tracks, or every file below SOURCE_DIR outside build folders)
set -uo pipefail
src=$1; shift
cd "$src" || exit 2
# The checks that look for these words on purpose, and their planted fixtures.
allowed='^(tests/docs/check_self_contained(_catches)?\.sh|tests/docs/planted_outside_refs\.md|tools/release/release_check\.cpp|tools/release/test_release_check\.sh)$'
if [ $# -gt 0 ]; then
  files=$(printf '%s\n' "$@")
elif [ -d .git ] || [ -f .git ]; then
  files=$(git ls-files)
else
  files=$(find . -type f -not -path './build*' -not -path '*/node_modules/*' | sed 's|^\./||')
fi
pattern='DESIGN(\.md| sections?\b| ?§)|\b[Ii]ssues? #?[0-9]+\b|\b[Ii]ssue #[0-9]+'
found=0
while IFS= read -r f; do
  [ -f "$f" ] || continue
  [[ "$f" =~ $allowed ]] && [ $# -eq 0 ] && continue
  case "$f" in *.png|*.exr|*.jpg|*.obj|*.zip|*.gz|*.ico) continue ;; esac
  grep -qI . "$f" 2>/dev/null || continue  # binary
  # A citation broken across two lines ("issue" at a line's end, its number
  # at the next one's start, after a comment marker) counts too.
  hits=$( { grep -nIE -- "$pattern" "$f"
            awk '/[Ii]ssues?[ \t]*$/ {held = FNR ": " $0; next}
                 held != "" && /^[ \t]*(\/\/|#|\*)?[ \t]*#?[0-9]+/ {print held " " $0}
                 {held = ""}' "$f"; } 2>/dev/null)
  [ -n "$hits" ] || continue
  while IFS= read -r h; do
    echo "$f:${h%%:*}: cites what the repository does not hold: ${h#*:}"
    found=$((found + 1))
  done <<< "$hits"
done <<< "$files"
if [ "$found" -gt 0 ]; then
  echo "$found citation(s) of documents or issues outside the repository (the design is docs/architecture.md)"
  exit 1
fi
echo "the repository cites nothing outside itself"
