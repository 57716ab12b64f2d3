#!/usr/bin/env bash
# The LÖVE checks of `make test`: a screenshot of every demo scene, made by the demo's
# scripted mode under xvfb-run, into DIR (emptied first); DIR/ok marks a complete set, and
# spec/demo_screenshot_spec.lua then checks each picture's colours where the shapes are.
# Then each example game runs for a few frames under LÖVE (tools/love-examples.sh).
# Installs Debian's love and xvfb when they are missing and this machine can (root +
# apt-get). Where it cannot, it says so and the screenshot spec stays pending: `make test`
# still passes on a machine without LÖVE, but .ci/run fails unless the screenshots ran.
#   bash tools/love-check.sh build/screenshots
set -u
[ $# -eq 1 ] || { echo "usage: $0 DIR" >&2; exit 2; }
dir=$1
rm -rf "$dir"
missing() {
  local m=()
  command -v love >/dev/null 2>&1 || m+=(love)
  command -v xvfb-run >/dev/null 2>&1 || m+=(xvfb xauth)
  echo "${m[@]}"
}
need=$(missing)
if [ -n "$need" ] && [ "${EUID:-$(id -u)}" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "== installing missing packages for the LÖVE checks: $need"
  # shellcheck disable=SC2086 # a list of package names
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $need >/dev/null 2>&1 \
    || { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $need >/dev/null; }
  need=$(missing)
fi
if [ -n "$need" ]; then
  echo "== LÖVE checks: SKIPPED, not installed: $need (Debian: sudo apt-get install love xvfb);"
  echo "   the screenshot spec stays pending"
  exit 0
fi
echo "== LÖVE checks: $(love --version 2>&1 | head -n 1), every demo scene drawn and every example run under xvfb-run"
bash "$(dirname "$0")/screenshots.sh" "$dir" || exit 1
touch "$dir/ok"
bash "$(dirname "$0")/love-examples.sh" || exit 1
