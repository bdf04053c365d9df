# Sourced by the release's tests (test_release.sh, test_student_journey.sh):
# run_section HEADING runs every command of every ```sh block under
# '## HEADING' of ./README.md (up to the next '## '), comments off, each as
# written; it fails at the first that fails.
run_section() {
  local cmds
  cmds=$(awk -v h="## $1" '$0==h{s=1;next} s&&/^## /{exit} s&&/^ *```sh/{b=1;next} b&&/^ *```/{b=0;next} s&&b{print}' README.md |
         sed 's/^[[:space:]]*//; s/[[:space:]]#.*$//; /^#/d' | sed '/^[[:space:]]*$/d')
  [ -n "$cmds" ] || { echo "README.md has no commands under '## $1'"; exit 1; }
  while IFS= read -r cmd; do
    echo "\$ $cmd"
    bash -c "$cmd"
  done <<< "$cmds"
}
