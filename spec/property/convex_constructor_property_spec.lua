-- Rectangle, RegularPolygon and Ellipse build their polygon without the hull when their points are
-- sure to be distinct and convex (ConvexPolygon._safeConvex): the result must be the very
-- polygon S.hapes.ConvexPolygon builds from the same points, slot for slot and bit for bit,
-- inside that range and at its edges. Reproduce a failure with STRIKE_SEED=<seed>.
local S = require('strike')
local PRNG = require('spec.helpers.prng')

local H = S.hapes
local SEED = PRNG.seedFromEnv(20261124)
local sin, cos, pi = math.sin, math.cos, math.pi

local function show(v) return type(v) == 'number' and ('%.17g'):format(v) or tostring(v) end

-- The two built polygons, brought to the same pose (the constructors put the centroid at
-- the exact centre, the general path at the computed centroid) and refreshed: every slot of
-- their tables and every number of their local geometry must be equal.
local function same(a, b, x, y, where)
  b:translateTo(x, y)
  a:getBounds()
  b:getBounds()
  assert(#a == #b, where .. ': slot counts ' .. #a .. ' and ' .. #b)
  for k = 1, #a do
    if a[k] ~= b[k] then
      error(('%s: slot %d is %s, the general path gives %s'):format(where, k, show(a[k]), show(b[k])))
    end
  end
  for k = 1, #b._l do
    if a._l[k] ~= b._l[k] then error(('%s: local geometry %d differs'):format(where, k)) end
  end
  assert(a:getKind() == b:getKind(), where .. ': kinds')
end

-- A centre: near the origin, or far from it (where the rounding of coordinates is coarse).
local function centre(rng)
  local far = 10 ^ rng:range(-3, 12)
  return rng:range(-far, far), rng:range(-far, far)
end

-- A size relative to the centre's magnitude, across the fast path's threshold (1e-6).
local function size(rng, x, y)
  local scale = math.max(1, math.abs(x) + math.abs(y))
  return scale * 10 ^ rng:range(-8, -1)
end

describe('Rectangle, RegularPolygon and Ellipse without the hull', function()
  it('build the polygon ConvexPolygon builds from their points (3,000 seeded cases each)', function()
    local rng = PRNG.new(SEED)
    local fast, general = 0, 0 -- (cases on each side of the threshold)
    for case = 1, 3000 do
      local where = ('seed %d case %d'):format(SEED, case)
      local x, y = centre(rng)
      local w, h = size(rng, x, y), size(rng, x, y)
      if rng:next() < 0.3 then x, y = math.floor(x), math.floor(y) end -- (integers: Lua 5.3+ keeps them apart)
      local ok, a = pcall(H.Rectangle, x, y, w, h)
      if ok then
        if S.hapes.ConvexPolygon._safeConvex(x, y, 4, math.min(w, h), (w + h) / 2) then
          fast = fast + 1
        else
          general = general + 1
        end
        local hx, hy = w / 2, h / 2
        local b = H.ConvexPolygon(x - hx, y - hy, x + hx, y - hy, x + hx, y + hy, x - hx, y + hy)
        same(a, b, x, y, where .. ' (Rectangle)')
      end
      local n, r = rng:int(3, 70), size(rng, x, y)
      local ok2, p = pcall(H.RegularPolygon, x, y, n, r)
      if ok2 then
        local pts = {}
        for i = 1, n do
          local t = -2 * pi * i / n
          pts[2 * i - 1], pts[2 * i] = x + r * sin(t), y + r * cos(t)
        end
        same(p, H.ConvexPolygon(pts), x, y, where .. ' (RegularPolygon)')
      end
    end
    assert(fast > 500 and general > 500, ('seed %d: %d fast and %d general cases'):format(SEED, fast, general))
  end)

  it('Ellipse: builds the polygon ConvexPolygon builds from its points (3,000 seeded cases)', function()
    -- (the fast path takes semi-axes within a ratio of 16 and at most 64 segments, in
    -- ConvexPolygon._safeConvex's range: the cases reach past each of those bounds)
    local rng = PRNG.new(SEED + 1)
    local fast, general = 0, 0
    for case = 1, 3000 do
      local where = ('seed %d case %d (Ellipse)'):format(SEED + 1, case)
      local x, y = centre(rng)
      local a = size(rng, x, y)
      -- (ratios mostly from about 1/32 to 32, some up to 1e12 either way: beyond about 1e9 the
      -- hull drops points it finds collinear, which a fast path without the bound would keep)
      local b = a * 10 ^ (rng:next() < 0.8 and rng:range(-1.5, 1.5) or rng:range(-12, 12))
      if rng:next() < 0.3 then x, y = math.floor(x), math.floor(y) end
      local n = rng:next() < 0.3 and rng:int(3, 80) or nil
      local ok, e = pcall(H.Ellipse, x, y, a, b, n)
      if ok then
        local segs = select(5, e:unpack())
        local lo, hi = math.min(a, b), math.max(a, b)
        if hi <= 16 * lo and S.hapes.ConvexPolygon._safeConvex(x, y, segs, 2 * lo * sin(pi / segs), hi) then
          fast = fast + 1
        else
          general = general + 1
        end
        local pts = {}
        for k = 1, segs do
          local t = 2 * pi * (k - 1) / segs
          pts[2 * k - 1], pts[2 * k] = x + a * cos(t), y + b * sin(t)
        end
        same(e, H.ConvexPolygon(pts), x, y, where)
      end
    end
    assert(fast > 500 and general > 500, ('seed %d: %d fast and %d general cases'):format(SEED + 1, fast, general))
  end)
end)
