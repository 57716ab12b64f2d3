#!/usr/bin/env bash
# Copy strike/ into libs/ of an empty folder and load it there under every VM, the way a
# game that vendors the folder would: `require 'libs.strike'` (with ./?/init.lua on the
# path, as LÖVE and Lua 5.2+ have) and `require 'libs.strike.init'` (plain 5.1 / LuaJIT).
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/game/libs" && cp -R "$here/strike" "$tmp/game/libs/strike"
status=0
for vm in "$@"; do
  for mod in libs.strike libs.strike.init; do
    if (cd "$tmp/game" && "$vm" -e "
      package.path = './?.lua;./?/init.lua;' .. package.path
      local S = require '$mod'
      local m = S.triking(S.trikers.Rectangle(0, 0, 10), S.trikers.Circle(7, 0, 3))
      assert(m and math.abs(m.x - 1) < 1e-12, 'wrong collision')
      for name in pairs(package.loaded) do assert(not name:match('^strike'), 'loaded ' .. name) end
      assert(S.trikers.Concave(0,0, 20,0, 20,10, 10,10, 10,20, 0,20):getShapeCount() == 2)
      local level = S.tiled({ tilewidth = 16, tileheight = 16, tilesets = {}, layers = { { type = 'objectgroup',
        name = 'walls', properties = { collidable = true }, objects = { { id = 1, shape = 'rectangle', x = 0, y = 0,
        width = 16, height = 8 } } } } }, S.pace())
      assert(#level.bodies == 1, 'S.tiled')
      for name in pairs(package.loaded) do assert(not name:match('^strike'), 'loaded ' .. name) end
    "); then :; else echo "copy-check: $vm could not use a copy as $mod" >&2; status=1; fi
  done
done
[ $status -eq 0 ] && echo "copy-check: a copy under libs/ loads under: $*"
exit $status
