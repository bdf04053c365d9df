# Sourced by the graders' entry points (gradescope/run_autograder,
# prairielearn/run_prairielearn): read_grading_args FILE sets the array
# grading_args to the course's extra arguments for pt-grade submission, one
# per line in FILE (none when FILE is missing); blank lines and lines starting
# with # are skipped.
read_grading_args() {
  grading_args=()
  [ -f "$1" ] || return 0
  local line
  while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in ''|'#'*) ;; *) grading_args+=("$line") ;; esac
  done < "$1"
}
