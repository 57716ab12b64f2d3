-- Property-based specs for S.triking between compound bodies: its MTV must be the
-- shortest translation of b that separates ALL of a's members from ALL of b's members,
-- as computed by the independent oracle in spec/property/union_oracle.lua (a certified
-- directional search over the union of the member pairs' Minkowski differences). Bodies
-- are read only through public accessors. Reproduce a failure with STRIKE_SEED=<seed>.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')
local brute = require('spec.property.brute')
local gen = require('spec.property.gen')
local oracle = require('spec.property.union_oracle')

local abs, min, sqrt, cos, sin, pi = math.abs, math.min, math.sqrt, math.cos, math.sin, math.pi
local logRange = gen.logRange

local SEED = PRNG.seedFromEnv(20250301)

-- Rounded bodies (Capsule, Rectangle and ConvexPolygon with a radius) are picked up as soon
-- as strike has them.
local ROUNDED = S.hapes.Capsule ~= nil

---------------------------------------------------------------------------------------
-- Bodies, each built from constructor arguments that are kept for failure messages.

local function showArgs(args)
  local parts = {}
  for i = 1, #args do
    local v = args[i]
    if type(v) == 'table' then
      local inner = {}
      for k = 1, #v do inner[k] = ('%.17g'):format(v[k]) end
      if v.radius then inner[#inner + 1] = ('radius = %.17g'):format(v.radius) end
      parts[i] = '{ ' .. table.concat(inner, ', ') .. ' }'
    elseif type(v) == 'number' then
      parts[i] = ('%.17g'):format(v)
    else
      parts[i] = tostring(v)
    end
  end
  return table.concat(parts, ', ')
end

-- S.hapes[name](...) (S.trikers[name] for colliders), and a string that rebuilds it.
local function build(group, name, ...)
  local body = S[group][name](...)
  return body, ('S.%s.%s(%s)'):format(group, name, showArgs({ ... }))
end

-- The hull of k random points in a disk of radius `size` about (cx, cy), as a flat list
-- (strike's ConvexPolygon takes convex outlines only), or nil when it is too flat.
local function hullPoints(rng, cx, cy, size)
  local xs, ys, k = {}, {}, rng:int(3, 10)
  for i = 1, k do
    local a, r = rng:range(0, 2 * pi), size * sqrt(rng:next())
    xs[i], ys[i] = cx + r * cos(a), cy + r * sin(a)
  end
  local hx, hy, h = brute.hull(xs, ys, k)
  if h < 3 or abs(brute.shoelace(hx, hy, h)) < 0.01 * size * size then return nil end
  local flat = {}
  for i = 1, h do flat[2 * i - 1], flat[2 * i] = hx[i], hy[i] end
  return flat
end

local KINDS = { 'rect', 'ngon', 'hull', 'circle' }
if ROUNDED then
  for _, k in ipairs({ 'capsule', 'roundrect', 'roundhull' }) do KINDS[#KINDS + 1] = k end
end

-- A random convex body of about `size` centred near (cx, cy): a polygon, a circle, or
-- (when strike has them) a rounded body. Returns the shape and its constructor call.
local function convexBody(rng, cx, cy, size, kinds)
  kinds = kinds or KINDS
  local kind = kinds[rng:int(1, #kinds)]
  local angle = rng:range(-pi, pi)
  if kind == 'rect' then
    return build('hapes', 'Rectangle', cx, cy, size * logRange(rng, 0.1, 2), size * logRange(rng, 0.1, 2), angle)
  elseif kind == 'ngon' then
    return build('hapes', 'RegularPolygon', cx, cy, rng:int(3, 12), size * logRange(rng, 0.2, 1), angle)
  elseif kind == 'circle' then
    return build('hapes', 'Circle', cx, cy, size * logRange(rng, 0.1, 1))
  elseif kind == 'capsule' then
    local w = size * logRange(rng, 0.1, 1)
    return build('hapes', 'Capsule', cx, cy, w, w + size * logRange(rng, 0.05, 2), angle)
  elseif kind == 'roundrect' then
    local w, h = size * logRange(rng, 0.1, 2), size * logRange(rng, 0.1, 2)
    return build('hapes', 'Rectangle', cx, cy, w, h, angle, min(w, h) / 2 * rng:range(0.05, 0.95))
  end
  -- 'hull' and 'roundhull'
  while true do
    local flat = hullPoints(rng, cx, cy, size)
    if flat then
      if kind == 'roundhull' then flat.radius = size * logRange(rng, 0.01, 0.5) end
      local ok, shape, text = pcall(build, 'hapes', 'ConvexPolygon', flat)
      if ok then return shape, text end
    end
  end
end

-- A random simple polygon of 4..maxN vertices, star-shaped about (cx, cy) (sorted random
-- angles, random radii in [0.2, 1] R), either winding, as S.trikers.Concave.
local function concaveBody(rng, cx, cy, R, maxN)
  local n = rng:int(4, maxN)
  local angles = gen.starAngles(rng, n)
  local flat = {}
  local reverse = rng:next() < 0.5
  for i = 1, n do
    local k = reverse and n + 1 - i or i
    local r = R * rng:range(0.2, 1)
    flat[2 * k - 1], flat[2 * k] = cx + r * cos(angles[i]), cy + r * sin(angles[i])
  end
  return build('trikers', 'Concave', flat)
end

-- A Collider of 2..6 convex members of about `size` around (cx, cy), each placed near an
-- earlier one so that they overlap.
local function compoundBody(rng, cx, cy, size)
  local members, texts, xs, ys = {}, {}, { cx }, { cy }
  for i = 1, rng:int(2, 6) do
    local j = rng:int(1, #xs)
    local d, t = size * rng:range(0, 0.6), rng:range(0, 2 * pi)
    local x, y = xs[j] + d * cos(t), ys[j] + d * sin(t)
    xs[#xs + 1], ys[#ys + 1] = x, y
    members[i], texts[i] = convexBody(rng, x, y, size * logRange(rng, 0.3, 1))
  end
  local c = S.trikers.Collider()
  for i = 1, #members do c:add(members[i]) end
  return c, 'S.trikers.Collider(' .. table.concat(texts, ', ') .. ')'
end

-- Move `body` (described by `text`) by a random offset of length up to `reach`.
local function nudge(rng, body, text, reach)
  local d, t = reach * rng:range(0, 1), rng:range(0, 2 * pi)
  local dx, dy = d * cos(t), d * sin(t)
  body:translate(dx, dy)
  return body, ('%s:translate(%.17g, %.17g)'):format(text, dx, dy)
end

---------------------------------------------------------------------------------------
-- The check, and a tally of failures per category.

local REL = 1e-6 -- |mtv| against the oracle's length
local TOL = 1e-9 -- times the scene's scale: overlap after moving, and touching

local function newTally(name)
  return { name = name, cases = 0, colliding = 0, skipped = 0, fails = 0, kinds = {}, errors = {}, first = nil }
end

-- Record a failing case: the ways it fails (a list of names) and its relative length error.
local function fail(tally, ways, text, err)
  tally.fails = tally.fails + 1
  local key = table.concat(ways, ' and ')
  tally.kinds[key] = (tally.kinds[key] or 0) + 1
  if err then tally.errors[#tally.errors + 1] = err end
  if not tally.first then tally.first = text end
end

-- Compare S.triking(a, b) with the oracle; `where` names the case.
local function check(tally, a, b, where)
  tally.cases = tally.cases + 1
  local A, B = oracle.members(a), oracle.members(b)
  local tol = TOL * oracle.scale(A, B)
  local tx, ty, L, info = oracle.solve(A, B)
  local res = S.triking(a, b)
  if not tx then
    if ty < tol then tally.skipped = tally.skipped + 1 return end -- (just touching)
    if res then
      fail(tally, { 'an MTV while apart' }, ('the oracle finds no collision (gap %.17g), yet S.triking returned '
        .. '(%.17g, %.17g): %s'):format(ty, res.x, res.y, where))
    end
    return
  end
  if L < tol then tally.skipped = tally.skipped + 1 return end -- (just touching)
  tally.colliding = tally.colliding + 1
  assert(info.unresolved <= tol, ('the oracle left a gap of %.17g unresolved: %s'):format(info.unresolved, where))
  assert(not oracle.overlaps(A, B, tx, ty, tol), 'the oracle\'s own translation does not separate: ' .. where)
  local expect = ('oracle (%.17g, %.17g), length %.17g'):format(tx, ty, L)
  if not res then
    fail(tally, { 'false while colliding' }, ('S.triking returned false; %s: %s'):format(expect, where))
    return
  end
  local len = sqrt(res.x * res.x + res.y * res.y)
  local got = ('S.triking (%.17g, %.17g), length %.17g; %s'):format(res.x, res.y, len, expect)
  local still, depth = oracle.overlaps(A, B, res.x, res.y, tol)
  local ways, why = {}, {}
  if still then
    ways[#ways + 1] = 'does not separate'
    why[#why + 1] = ('after moving b by the MTV a pair still overlaps by %.17g'):format(depth)
  end
  if len > L * (1 + REL) + tol then
    ways[#ways + 1] = 'too long'
    why[#why + 1] = 'the MTV is longer than needed'
  elseif len < L * (1 - REL) - tol then
    -- a shorter translation that separates: the oracle missed it
    assert(still, ('the MTV separates and is shorter than the oracle\'s: the ORACLE is wrong; %s: %s')
      :format(got, where))
    ways[#ways + 1] = 'too short'
    why[#why + 1] = 'the MTV is shorter than the shortest separating translation'
  end
  if abs(res.depth - len) > tol + REL * len then
    ways[#ways + 1] = 'depth is not |(x, y)|'
    why[#why + 1] = ('its depth is %.17g'):format(res.depth)
  end
  if #ways > 0 then
    fail(tally, ways, ('%s; %s: %s'):format(table.concat(why, '; '), got, where), abs(len - L) / L)
  end
end

-- check for the compound c (text tc) and the body b (text tb) in case `case`: c first in even
-- cases, b first in odd ones (the MTV must hold in both orders).
local function checkEitherOrder(tally, case, c, tc, b, tb)
  if case % 2 == 0 then
    check(tally, c, b, ('seed %d case %d: a = %s; b = %s'):format(SEED, case, tc, tb))
  else
    check(tally, b, c, ('seed %d case %d: a = %s; b = %s'):format(SEED, case, tb, tc))
  end
end

local function verdict(tally)
  if tally.fails == 0 then return end
  local kinds = {}
  for k, c in pairs(tally.kinds) do kinds[#kinds + 1] = ('%d %s'):format(c, k) end
  table.sort(kinds)
  local errors = tally.errors
  table.sort(errors)
  local stats = ''
  if #errors > 0 then
    stats = ('; relative length error of the failing MTVs: median %.3g, worst %.3g')
      :format(errors[math.ceil(#errors / 2)], errors[#errors])
  end
  error(('seed %d, %s: %d of %d cases fail (%d colliding, %d skipped as touching): %s%s. First: %s')
    :format(SEED, tally.name, tally.fails, tally.cases, tally.colliding, tally.skipped, table.concat(kinds, ', '),
    stats, tally.first), 0)
end

---------------------------------------------------------------------------------------

-- Case counts on LuaJIT (a quarter on Lua 5.1-5.4; LuaJIT's past the first 30 interpreted:
-- spec/helpers/budget.lua).
local COUNT = {
  convex = 2000,
  concave = 2000,
  compound = 1500,
  compounds = 1000,
}

describe('compound MTV oracle (spec/property/union_oracle.lua)', function()
  local function box(x0, y0, x1, y1, r)
    return { xs = { x0, x1, x1, x0 }, ys = { y0, y0, y1, y1 }, n = 4, r = r or 0 }
  end
  local function circle(x, y, r) return { xs = { x }, ys = { y }, n = 1, r = r } end
  local function expectSolution(A, B, ex, ey)
    local tx, ty, L, info = oracle.solve(A, B)
    assert(tx, 'the oracle finds no collision')
    local want = sqrt(ex * ex + ey * ey)
    assert(abs(L - want) <= 1e-10 * want, ('length %.17g, want %.17g'):format(L, want))
    -- (at a smooth minimum the length is quadratic in the angle: the direction is only
    -- as good as the square root of the length's accuracy)
    assert(abs(tx - ex) <= 1e-4 * want and abs(ty - ey) <= 1e-4 * want,
      ('translation (%.17g, %.17g), want (%.17g, %.17g)'):format(tx, ty, ex, ey))
    assert(info.unresolved == 0, 'unresolved')
    assert(not oracle.overlaps(A, B, tx, ty, 1e-12), 'its own answer does not separate')
    assert(oracle.overlaps(A, B, tx * 0.999, ty * 0.999, 0), 'a shorter one separates too')
  end

  it('solves two squares', function()
    expectSolution({ box(0, 0, 2, 2) }, { box(1, 0.5, 3, 2.5) }, 1, 0)
  end)

  it('solves two circles', function()
    expectSolution({ circle(0, 0, 1) }, { circle(1.5, 0, 1) }, 0.5, 0)
    expectSolution({ circle(0, 0, 1) }, { circle(0.3, 0.4, 0.5) }, 0.6 * 1.5 - 0.3, 0.8 * 1.5 - 0.4)
  end)

  it('solves a circle in the inner corner of an L (the sharp corner of the union)', function()
    -- the centre must leave both arms by 0.5: the free corner is (1.5, 1.5)
    expectSolution({ box(0, 0, 4, 1), box(0, 1, 1, 4) }, { circle(1.2, 1.3, 0.5) }, 0.3, 0.2)
  end)

  it('solves a box sunk into the seam between two tiles', function()
    -- the nearest way out of either tile alone is sideways (0.05), into the other tile
    expectSolution({ box(0, 0, 1, 1), box(1, 0, 2, 1) }, { box(0.95, 0.9, 1.05, 1.2) }, 0, 0.1)
  end)

  it('solves a rounded box against a rounded box', function()
    -- cores [0, 2]^2 and [2.5, 3]x[0, 1], radii 0.5 and 0.25: the gap 0.5 < 0.75
    expectSolution({ box(0, 0, 2, 2, 0.5) }, { box(2.5, 0, 3, 1, 0.25) }, 0.25, 0)
    -- a capsule (segment core) across a circle
    expectSolution({ { xs = { -3, 3 }, ys = { 0, 0 }, n = 2, r = 1 } }, { circle(0.5, 1.5, 1) }, 0, 0.5)
  end)

  it('finds a narrow free pocket: a box that just fits a hole in a wall', function()
    -- the hole [0, 1]^2 in the wall [-5, 6]x[-5, 6]; the 0.999-wide box fits in it after a
    -- move of (0.5, -2.5) + [0, 0.001]^2, a pocket 0.0004 rad wide seen from the origin
    local wall = { box(-5, -5, 0, 6), box(1, -5, 6, 6), box(0, -5, 1, 0), box(0, 1, 1, 6) }
    expectSolution(wall, { box(-0.5, 2.5, 0.499, 3.499) }, 0.5, -2.499)
  end)

  it('reports no collision when the bodies only touch or are apart', function()
    assert.is_nil((oracle.solve({ box(0, 0, 1, 1) }, { box(1, 0, 2, 1) })))
    assert.is_nil((oracle.solve({ circle(0, 0, 1) }, { circle(2, 0, 1) })))
    local _, gap = oracle.solve({ box(0, 0, 1, 1) }, { circle(3, 0.5, 1) })
    assert(abs(gap - 1) < 1e-15, 'gap')
  end)

  -- The branch and bound's certificate, checked: a dense sweep of directions (f exact in
  -- each) never finds a shorter way out than the oracle, and comes close to it (a V-shaped
  -- minimum or a narrow pocket between the sampled directions keeps it above).
  it('is never beaten by a dense sweep of directions on random compound pairs', function()
    local rng = PRNG.new(SEED + 59)
    for case = 1, 40 do
      local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
      local size = logRange(rng, 0.5, 4)
      local a, ta
      if case % 2 == 0 then a, ta = concaveBody(rng, ox, oy, size, 20) else a, ta = compoundBody(rng, ox, oy, size) end
      local b, tb = compoundBody(rng, ox, oy, size * logRange(rng, 0.3, 1))
      b, tb = nudge(rng, b, tb, size)
      local A, B = oracle.members(a), oracle.members(b)
      local _, _, L = oracle.solve(A, B)
      if L then
        local Ms, sweep = oracle.differences(A, B), math.huge
        for k = 1, 1000 do sweep = min(sweep, oracle.exit(Ms, (k + 0.5) * pi / 500)) end
        local where = ('seed %d case %d: a = %s; b = %s'):format(SEED, case, ta, tb)
        assert(sweep >= L * (1 - 1e-10), ('the sweep finds %.17g, the oracle %.17g: %s'):format(sweep, L, where))
        assert(sweep <= L * 1.1, ('the sweep finds only %.17g, the oracle %.17g: %s'):format(sweep, L, where))
      end
    end
  end)

  it('reads members through public accessors', function()
    local c = S.trikers.Collider(S.hapes.Rectangle(0, 0, 2, 2), S.hapes.Circle(5, 1, 0.5))
    local m = oracle.members(c)
    assert.equal(2, #m)
    local seen = {}
    for i = 1, 2 do seen[m[i].n] = m[i] end
    assert(seen[4] and seen[4].r == 0 and seen[1] and seen[1].r == 0.5 and seen[1].xs[1] == 5)
  end)
end)

describe('S.triking between compound bodies (oracle: the shortest translation separating all members)',
  function()
    it('single convex bodies against each other', function()
      local rng = PRNG.new(SEED + 60)
      local tally = newTally('convex vs convex')
      budget.loop(COUNT.convex, function(case)
        local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
        local size = logRange(rng, 0.3, 5)
        local a, ta = convexBody(rng, ox, oy, size)
        local b, tb = convexBody(rng, ox, oy, size * logRange(rng, 0.2, 2))
        b, tb = nudge(rng, b, tb, 1.2 * size)
        check(tally, a, b, ('seed %d case %d: a = %s; b = %s'):format(SEED, case, ta, tb))
      end)
      verdict(tally)
    end)

    it('convex bodies against concave outlines (S.trikers.Concave, up to 30 vertices)', function()
      local rng = PRNG.new(SEED + 61)
      local tally = newTally('convex vs concave')
      budget.loop(COUNT.concave, function(case)
        local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
        local R = logRange(rng, 1, 8)
        local c, tc = concaveBody(rng, ox, oy, R, 30)
        local b, tb = convexBody(rng, ox, oy, R * logRange(rng, 0.05, 0.8))
        b, tb = nudge(rng, b, tb, 1.1 * R)
        checkEitherOrder(tally, case, c, tc, b, tb)
      end)
      verdict(tally)
    end)

    it('compounds of 2-6 members against convex bodies', function()
      local rng = PRNG.new(SEED + 62)
      local tally = newTally('compound vs convex')
      budget.loop(COUNT.compound, function(case)
        local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
        local size = logRange(rng, 0.5, 4)
        local c, tc = compoundBody(rng, ox, oy, size)
        local b, tb = convexBody(rng, ox, oy, size * logRange(rng, 0.2, 2))
        b, tb = nudge(rng, b, tb, 1.5 * size)
        checkEitherOrder(tally, case, c, tc, b, tb)
      end)
      verdict(tally)
    end)

    it('compounds against compounds and concave outlines', function()
      local rng = PRNG.new(SEED + 63)
      local tally = newTally('compound vs compound')
      -- each side a Collider, or (one time in three) a concave outline
      local function side(ox, oy, size)
        if rng:next() < 1 / 3 then return concaveBody(rng, ox, oy, size, 16) end
        return compoundBody(rng, ox, oy, size)
      end
      budget.loop(COUNT.compounds, function(case)
        local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
        local size = logRange(rng, 0.5, 4)
        local a, ta = side(ox, oy, size)
        local b, tb = side(ox, oy, size * logRange(rng, 0.5, 2))
        b, tb = nudge(rng, b, tb, 1.5 * size)
        check(tally, a, b, ('seed %d case %d: a = %s; b = %s'):format(SEED, case, ta, tb))
      end)
      verdict(tally)
    end)
  end)
