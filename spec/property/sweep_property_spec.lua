-- Property specs for S.weep (translation) and S.eparation against an independent oracle:
-- brute.signedDistance, the distance from the origin to the hull of every vertex difference
-- of the two cores (the Minkowski difference, built point by point), less the radii. Each
-- shape is read through its public getters only (vertices, centre, radius, rounding).
-- Along a translation the distance between two convex shapes is a convex function of t, so
-- the oracle finds its minimum by ternary search. Reproduce a failure with STRIKE_SEED=<seed>.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')
local brute = require('spec.property.brute')
local gen = require('spec.property.gen')

local H = S.hapes
local abs, sqrt, cos, sin, pi, max = math.abs, math.sqrt, math.cos, math.sin, math.pi, math.max
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

local SEED = PRNG.seedFromEnv(20261124)
local CASES = budget.cases(3000) -- (a quarter on Lua 5.1-5.4: spec/helpers/budget.lua)

-- The oracle's record of a shape: brute.of plus the rounding radius of a rounded shape.
local function record(s)
  local o = brute.of(s)
  if not o.circle then o.r = s:getRounding() end
  return o
end

-- The record moved by (dx, dy).
local function moved(o, dx, dy)
  if o.circle then return { circle = true, x = o.x + dx, y = o.y + dy, r = o.r } end
  local xs, ys = {}, {}
  for i = 1, o.n do xs[i], ys[i] = o.xs[i] + dx, o.ys[i] + dy end
  return { xs = xs, ys = ys, n = o.n, r = o.r }
end

-- Signed distance from (x, y) to the shape of record o.
local function pointDist(o, x, y)
  if o.circle then return sqrt((x - o.x) ^ 2 + (y - o.y) ^ 2) - o.r end
  return brute.pointSignedDist(o, x, y) - o.r
end

-- Shapes: the generator's kinds, plus capsules, rounded rectangles and points.
local KINDS = { 'rect', 'ngon', 'hull', 'ellipse', 'circle', 'edge', 'capsule', 'roundrect', 'point' }
local function shape(rng, kind, x, y)
  local a = rng:range(-pi, pi)
  if kind == 'capsule' then
    local w = gen.logRange(rng, 0.2, 6)
    return H.Capsule(x, y, w, w + gen.logRange(rng, 0.1, 10), a)
  elseif kind == 'roundrect' then
    local w, h = gen.logRange(rng, 0.5, 10), gen.logRange(rng, 0.5, 10)
    return H.Rectangle(x, y, w, h, a, rng:range(0.01, 0.49) * math.min(w, h))
  elseif kind == 'point' then
    return H.Point(x, y)
  end
  return gen.shape(S, rng, kind, x, y)
end

local function g(v) return ('%.17g'):format(v) end
local function show(s, o)
  local t = { s.name }
  if o.circle then
    t[#t + 1] = ('centre (%s, %s) r %s'):format(g(o.x), g(o.y), g(o.r))
  else
    for i = 1, o.n do t[#t + 1] = ('(%s, %s)'):format(g(o.xs[i]), g(o.ys[i])) end
    t[#t + 1] = 'r ' .. g(o.r)
  end
  return table.concat(t, ' ')
end

-- A random separated pair and a move of a that often reaches b: a, b, oa, ob, dx, dy.
local function case(rng)
  while true do
    local ox, oy = rng:range(-60, 60), rng:range(-60, 60)
    local a = shape(rng, KINDS[rng:int(1, #KINDS)], ox, oy)
    local t = rng:range(0, 2 * pi)
    local d = rng:range(0.2, 3) * (a:getRadius() + 6)
    local b = shape(rng, KINDS[rng:int(1, #KINDS)], ox + d * cos(t), oy + d * sin(t))
    local oa, ob = record(a), record(b)
    if brute.signedDistance(oa, ob) > 1e-3 then
      local bx, by = b:getCentroid()
      local k = rng:range(0, 2)
      local s = a:getRadius() + b:getRadius()
      return a, b, oa, ob, (bx - ox) * k + rng:range(-1, 1) * s, (by - oy) * k + rng:range(-1, 1) * s
    end
  end
end

describe('S.weep against an independent oracle (translation)', function()
  it('a hit touches at t, is apart just before, and separates along its normal; a miss never overlaps',
    function()
      local rng = PRNG.new(SEED)
      local hit, out = 0, {}
      for n = 1, CASES do
        local a, b, oa, ob, dx, dy = case(rng)
        local function f(t) return (brute.signedDistance(moved(oa, t * dx, t * dy), ob)) end
        local scale = brute.scale(oa, ob) + abs(dx) + abs(dy)
        local tol = 1e-9 * scale
        local h = S.weep(a, dx, dy, b, nil, out)
        local function fail(msg)
          error(('seed %d case %d: %s\n  a %s\n  b %s\n  move (%s, %s)%s'):format(SEED, n, msg, show(a, oa),
            show(b, ob), g(dx), g(dy), h and (' hit t %s at (%s, %s) normal (%s, %s)'):format(g(h.t), g(h.x),
              g(h.y), g(h.nx), g(h.ny)) or ' no hit'))
        end
        if h then
          hit = hit + 1
          assert(h == out)
          if h.overlapping then fail('a separated start reported as overlapping') end
          if not (h.t >= 0 and h.t <= 1) then fail('t out of [0, 1]') end
          if abs(f(h.t)) > tol then fail('not touching at t: distance ' .. g(f(h.t))) end
          -- luacheck: ignore 581 (a NaN must fail)
          if h.t > 1e-6 and not (f(h.t - 1e-6) > 0) then fail('touching before t') end
          if abs(h.nx * h.nx + h.ny * h.ny - 1) > 1e-12 then fail('normal not unit') end
          local e = 1e-6 * scale
          local sep = brute.signedDistance(moved(oa, h.t * dx + e * h.nx, h.t * dy + e * h.ny), ob)
          -- luacheck: ignore 581 (a NaN must fail)
          if not (sep > 0) then fail('moving a along the normal does not separate them') end
          local at = moved(oa, h.t * dx, h.t * dy)
          if abs(pointDist(at, h.x, h.y)) > 1e-7 * scale or abs(pointDist(ob, h.x, h.y)) > 1e-7 * scale then
            fail('contact point not on both surfaces')
          end
        else
          local lo, hi = 0, 1 -- the minimum of the convex f over [0, 1]
          for _ = 1, 100 do
            local m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
            if f(m1) < f(m2) then hi = m2 else lo = m1 end
          end
          if f((lo + hi) / 2) < -tol then fail('missed: they overlap at t = ' .. g((lo + hi) / 2)) end
        end
      end
      assert(hit > CASES / 4 and hit < CASES * 3 / 4, 'hits: ' .. hit) -- (both branches are exercised)
    end)

  it('S.eparation: the distance and the closest points, or minus the depth', function()
    local rng = PRNG.new(SEED + 1)
    for n = 1, CASES do
      local a, b, oa, ob, dx, dy = case(rng)
      if n % 2 == 0 then -- half of them moved into overlap or near it
        local k = rng:range(0.3, 1)
        a:translate(k * dx, k * dy)
        oa = record(a)
      end
      local want = brute.signedDistance(oa, ob)
      local scale = brute.scale(oa, ob)
      local d, ax, ay, bx, by = S.eparation(a, b)
      local function fail(msg)
        error(('seed %d case %d: %s\n  a %s\n  b %s\n  got %s (%s, %s) (%s, %s), oracle %s'):format(SEED + 1, n, msg,
          show(a, oa), show(b, ob), g(d), g(ax), g(ay), g(bx), g(by), g(want)))
      end
      if want > 0 then
        if abs(d - want) > 1e-9 * scale then fail('distance') end
        if abs(pointDist(oa, ax, ay)) > 1e-9 * scale or abs(pointDist(ob, bx, by)) > 1e-9 * scale then
          fail('closest points not on the surfaces')
        end
        if abs(sqrt((ax - bx) ^ 2 + (ay - by) ^ 2) - d) > 1e-9 * scale then fail('points not d apart') end
      elseif want < -1e-9 * scale then
        -- overlapping: minus S.triking's depth (which the SAT specs check against the oracle),
        -- and the points of a and of b farthest into each other along its MTV: on each surface,
        -- the depth apart along it
        local m = S.triking(a, b)
        if not m then fail('the oracle overlaps, S.triking does not') end
        if abs(d + m.depth) > 1e-12 * max(1, scale) then fail('not minus the depth') end
        if abs(pointDist(oa, ax, ay)) > 1e-9 * scale or abs(pointDist(ob, bx, by)) > 1e-9 * scale then
          fail('points not on the surfaces')
        end
        if abs((ax - bx) * m.nx + (ay - by) * m.ny - m.depth) > 1e-9 * scale then
          fail('points not the depth apart along the MTV')
        end
      end
    end
  end)

  it('with rotation: touching within the tolerance at t, apart at every sampled time before it, and a miss'
    .. ' overlaps at no sampled time', function()
    local rng = PRNG.new(SEED + 2)
    local hits = 0
    for n = 1, CASES / 3 do
      local a, b, _, ob, dx, dy = case(rng)
      local angle = rng:range(-4, 4)
      local cx, cy = a:getCentroid()
      local function at(t) -- the oracle's record of a copy of a, turned and moved to time t
        local c = a:copy()
        c:rotate(angle * t, cx, cy)
        c:translate(t * dx, t * dy)
        return record(c)
      end
      local size = a:getRadius() + b:getRadius()
      local h = S.weep(a, dx, dy, b, angle)
      local function fail(msg)
        error(('seed %d case %d: %s (angle %s, move (%s, %s), t %s)'):format(SEED + 2, n, msg, g(angle), g(dx), g(dy),
          h and g(h.t) or 'none'))
      end
      local until_ = h and h.t or 1
      for k = 0, 63 do
        local t = until_ * k / 64
        if h and t >= h.t then break end
        if brute.signedDistance(at(t), ob) < (h and 0 or -1e-9 * size) then fail('they meet before t') end
      end
      if h then
        hits = hits + 1
        local d = brute.signedDistance(at(h.t), ob)
        -- luacheck: ignore 581 (a NaN must fail)
        if not (abs(d) <= 1e-6 * size) then fail('not touching at t: distance ' .. g(d)) end
        if abs(h.nx * h.nx + h.ny * h.ny - 1) > 1e-9 then fail('normal not unit') end
      end
    end
    assert(hits > CASES / 12 and hits < CASES / 4, 'hits: ' .. hits)
  end)

  it('bodies of several members: the earliest of their members\' hits', function()
    local rng = PRNG.new(SEED + 3)
    for n = 1, 300 do
      local ox, oy = rng:range(-60, 60), rng:range(-60, 60)
      local parts, bparts = {}, {}
      for i = 1, rng:int(1, 3) do
        parts[i] = shape(rng, KINDS[rng:int(1, #KINDS)], ox + rng:range(-5, 5), oy + rng:range(-5, 5))
      end
      for i = 1, rng:int(1, 3) do
        bparts[i] = shape(rng, KINDS[rng:int(1, #KINDS)], ox + 25 + rng:range(-5, 5), oy + rng:range(-5, 5))
      end
      local a, b = S.trikers.Collider(unpack(parts)), S.trikers.Collider(unpack(bparts))
      if not S.triking(a, b) then
        local dx, dy = rng:range(10, 50), rng:range(-10, 10)
        local h = S.weep(a, dx, dy, b)
        local best = false -- the earliest pair, measured on fresh copies of the members
        for i = 1, #parts do
          for j = 1, #bparts do
            local p = S.weep(parts[i]:copy(), dx, dy, bparts[j]:copy())
            if p and (not best or p.t < best) then best = p.t end
          end
        end
        if (h and h.t) ~= best and not (h and best and abs(h.t - best) <= 1e-12) then
          error(('seed %d case %d: body hit %s, earliest member hit %s'):format(SEED + 3, n, tostring(h and h.t),
            tostring(best)))
        end
      end
    end
  end)
end)
