-- strike/geometry/hull.lua's helpers against plain oracles, on seeded random point sets with
-- duplicates and collinear points (small sets take the insertion sort, larger ones
-- table.sort). STRIKE_SEED picks the seed.
local hull = require('strike.geometry.hull')
local PRNG = require('spec.helpers.prng')

local SEED = PRNG.seedFromEnv(20261124)

-- n points on a small grid, some moved off it, some repeated.
local function points(rng)
  local n = rng:int(1, 24)
  local xs, ys = {}, {}
  for i = 1, n do
    if i > 1 and rng:int(1, 4) == 1 then
      local j = rng:int(1, i - 1)
      xs[i], ys[i] = xs[j], ys[j]
    else
      xs[i] = rng:int(-3, 3) + (rng:int(1, 3) == 1 and rng:range(0, 1) or 0)
      ys[i] = rng:int(-3, 3)
    end
  end
  return xs, ys, n
end

describe('strike.geometry.hull', function()
  it('orders points by x, then y, then index, as a sort by that key does', function()
    local rng = PRNG.new(SEED)
    for case = 1, 3000 do
      local xs, ys, n = points(rng)
      local want = {}
      for i = 1, n do want[i] = i end
      table.sort(want, function(a, b)
        if xs[a] ~= xs[b] then return xs[a] < xs[b] end
        if ys[a] ~= ys[b] then return ys[a] < ys[b] end
        return a < b
      end)
      local got = hull.order(xs, ys, n)
      for i = 1, n do
        if got[i] ~= want[i] then
          error(('case %d: position %d is point %s, want %d (STRIKE_SEED=%d reproduces)'):format(case, i,
            tostring(got[i]), want[i], SEED))
        end
      end
      assert.equals(n, #got)
    end
  end)

  it('starts a hull at a given vertex, as a rotated copy does', function()
    local rng = PRNG.new(SEED + 1)
    for case = 1, 3000 do
      local hx, hy, h = hull.build(points(rng))
      if h >= 1 then
        local s = rng:int(1, h)
        local wx, wy = {}, {}
        for i = 1, h do
          local j = (i + s - 2) % h + 1
          wx[i], wy[i] = hx[j], hy[j]
        end
        hull.startAt(hx, hy, h, wx[1], wy[1])
        for i = 1, h do
          if hx[i] ~= wx[i] or hy[i] ~= wy[i] then
            error(('case %d: vertex %d differs (STRIKE_SEED=%d reproduces)'):format(case, i, SEED))
          end
        end
        assert.equals(h, #hx)
      end
    end
  end)

  it('tells a point strictly inside a hull from one on or outside it', function()
    local rng = PRNG.new(SEED + 2)
    for case = 1, 3000 do
      local hx, hy, h = hull.build(points(rng))
      if h >= 3 then
        for i = 1, h do -- (a vertex is on the outline)
          assert(not hull.strictlyInside(hx, hy, h, hx[i], hy[i]), ('case %d: vertex %d inside'):format(case, i))
        end
        local x, y = rng:range(-4, 4), rng:range(-4, 4)
        -- the oracle: strictly left of every edge by more than the tolerance (a sine of 1e-10)
        local inside = true
        for i = 1, h do
          local j = i % h + 1
          local ex, ey, px, py = hx[j] - hx[i], hy[j] - hy[i], x - hx[i], y - hy[i]
          local c = ex * py - ey * px
          local tol = 1e-10 * math.sqrt(ex * ex + ey * ey) * math.sqrt(px * px + py * py)
          if not (c > tol) then inside = false end -- luacheck: ignore 581 (NaN is not inside)
        end
        assert(hull.strictlyInside(hx, hy, h, x, y) == inside,
          ('case %d: (%s, %s) (STRIKE_SEED=%d reproduces)'):format(case, x, y, SEED))
      end
    end
  end)
end)
