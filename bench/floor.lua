--- A box against a 20-tile floor (a collider of 20 touching 32 px Rectangles), the case the
--- outline rule (strike/collide/outline.lua) must keep cheap: S.triking(floor, box) per
--- second, for a box on one tile, across a seam, in an L's corner (the outline rule's full
--- search), and clear of the floor. Not part of make test; run it from any strike checkout:
---   lua bench/floor.lua [seconds per row, default 1]
--- (make bench runs the peers side by side; this row is strike against itself, before and
--- after a change: run it in both checkouts, one after the other, a few times.)
package.path = './?.lua;./?/init.lua;' .. package.path
local S = require('strike')
local H, T = S.hapes, S.trikers
local clock = os.clock
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

local seconds = tonumber(arg and arg[1]) or 1

local tiles = {}
for i = 0, 19 do tiles[#tiles + 1] = H.Rectangle(16 + 32 * i, 16, 32, 32) end
local floor = T.Collider(unpack(tiles))
local L = T.Concave(0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100)

local rows = {
  { 'box on one tile (10 deep)', floor, H.Rectangle(336, -10, 24, 40) },
  { 'box across a seam (10 deep)', floor, H.Rectangle(320, -10, 40, 40) },
  { 'box across a seam (20 deep)', floor, H.Rectangle(320, 0, 40, 40) },
  { 'box clear of the floor', floor, H.Rectangle(320, -40, 40, 40) },
  { 'circle in an L\'s corner', L, H.Circle(10, 10, 3) },
}

local out = S.MTV()
for _, row in ipairs(rows) do
  local a, b = row[2], row[3]
  for _ = 1, 1000 do S.triking(a, b, out) end -- (warm up: LuaJIT traces)
  local n, t0 = 0, clock()
  local t = t0
  while t - t0 < seconds do
    for _ = 1, 1000 do S.triking(a, b, out) end
    n = n + 1000
    t = clock()
  end
  io.stdout:write(('%-30s %9.0f calls/s\n'):format(row[1], n / (t - t0)))
end
