#!/usr/bin/env bash
# Make sure the commands `make test` needs exist; install the Debian packages that
# provide them when this machine can (root + apt-get), else print what to install.
set -u
declare -A pkg_of=(
  [lua5.1]=lua5.1 [lua5.2]=lua5.2 [lua5.3]=lua5.3 [lua5.4]=lua5.4 [luajit]=luajit
  [busted]=lua-busted [luacheck]=lua-check [luarocks]=luarocks
)
missing=()
for cmd in "$@" busted luacheck luarocks; do
  command -v "$cmd" >/dev/null 2>&1 || missing+=("${pkg_of[$cmd]:-$cmd}")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "== installing missing packages: ${missing[*]}"
if [ "${EUID:-$(id -u)}" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq "${missing[@]}" >/dev/null && exit 0
  echo "apt-get could not install: ${missing[*]}" >&2
  exit 1
fi
echo "missing: ${missing[*]}" >&2
echo "install them with: sudo apt-get install ${missing[*]}" >&2
echo "(other systems: the Lua VMs $*, LuaRocks, and busted and luacheck from LuaRocks)" >&2
exit 1
