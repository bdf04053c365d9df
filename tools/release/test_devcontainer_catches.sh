#!/usr/bin/env bash
# check_devcontainer.cmake fails on each fault planted in a copy of the
# definition (ctest: release:devcontainer-catches).
# Usage: test_devcontainer_catches.sh CHECKOUT WORKDIR
set -euo pipefail
source=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
plant() {  # plant NAME COMMAND: the check must fail on the copy COMMAND leaves
  local name=$1 cmd=$2
  rm -rf "$work/$name" && mkdir -p "$work/$name/.devcontainer" "$work/$name/skeleton/app"
  cp "$source/.devcontainer/devcontainer.json" "$work/$name/.devcontainer/"
  cp "$source/setup.sh" "$work/$name/"
  cp "$source/skeleton/app/cli.cpp" "$work/$name/skeleton/app/"
  (cd "$work/$name" && eval "$cmd")
  if cmake -DTREE="$work/$name" -P "$here/check_devcontainer.cmake" > "$work/$name.out" 2>&1; then
    echo "$name: not caught"; exit 1
  fi
  echo "$name: caught: $(grep -A1 'CMake Error' "$work/$name.out" | tail -1 | sed 's/^ *//')"
}
plant ubuntu_image "sed -i 's/debian:bookworm/ubuntu:22.04/' .devcontainer/devcontainer.json"
plant full_setup "sed -i 's|./setup.sh --deps-only|./setup.sh|' .devcontainer/devcontainer.json"
plant no_deps_only_step "sed -i '/--deps-only\" ] && exit 0/d' setup.sh"
plant port_moved "sed -i 's/int port = 8642;/int port = 8643;/' skeleton/app/cli.cpp"
plant comment "sed -i '1a // a comment' .devcontainer/devcontainer.json"
plant missing "rm .devcontainer/devcontainer.json"
rm -rf "$work"
echo "every planted fault caught"
