-- Property-based specs for the narrow phase, S.AT, against the independent oracle in
-- spec/property/brute.lua. Reproduce a failure with STRIKE_SEED=<seed> (any VM); the
-- message names the seed, the case index and the shapes at full precision.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')
local gen = require('spec.property.gen')

local abs, max, cos, sin, pi = math.abs, math.max, math.cos, math.sin, math.pi

local SEED = PRNG.seedFromEnv(20240611)

-- Every convex pair type, in both argument orders ('poly' is a random polygon kind:
-- rotated rectangle, regular 3..16-gon, hull of random points, or ellipse).
local PAIR_TYPES = {
  { 'poly', 'poly' },
  { 'circle', 'poly' }, { 'poly', 'circle' },
  { 'circle', 'circle' },
  { 'edge', 'poly' }, { 'poly', 'edge' },
  { 'edge', 'circle' }, { 'circle', 'edge' },
  { 'edge', 'edge' },
}

local function show(a, b)
  return ('a = %s; b = %s'):format(gen.show(a), gen.show(b))
end

local function mtvText(m)
  return ('mtv (%.17g, %.17g) n (%.17g, %.17g) depth %.17g separating %s'):format(
    m.x, m.y, m.nx, m.ny, m.depth, tostring(m.separating))
end

-- Verdict agreement for `perType` cases of every pair type, drawn from the stream
-- SEED + offset (messages report SEED, the value to put in STRIKE_SEED); `grid` draws
-- shapes on the integer grid. Pairs alternate between overlapping and not (per the oracle). Cases
-- within 1e-9 (times the coordinate scale) of touching are skipped, not asserted.
local function verdictProperty(offset, perType, grid)
  local seed = SEED
  local rng = PRNG.new(SEED + offset)
  local case, skipped = 0, 0
  for _, ty in ipairs(PAIR_TYPES) do
    for k = 1, perType do
      case = case + 1
      local a, b = gen.pair(S, rng, ty[1], ty[2], k % 2 == 0, grid)
      local da, db = brute.of(a), brute.of(b)
      local sd = brute.signedDistance(da, db)
      if abs(sd) <= 1e-9 * brute.scale(da, db) then
        skipped = skipped + 1
      else
        local want = brute.overlaps(da, db)
        -- the oracle's two views (clipping, Minkowski difference) must agree first
        assert(want == (sd < 0), ('seed %d case %d: ORACLE self-disagreement: overlaps %s, signed distance %.17g; %s')
          :format(seed, case, tostring(want), sd, show(a, b)))
        local m = S.AT(a, b)
        -- every field finite and the normal a unit vector, whatever the verdict
        local finite = true
        for _, v in ipairs({ m.x, m.y, m.nx, m.ny, m.depth }) do
          finite = finite and v == v and v ~= 1 / 0 and v ~= -1 / 0
        end
        assert(finite and abs(m.nx * m.nx + m.ny * m.ny - 1) <= 1e-12, ('seed %d case %d (%s-%s): malformed MTV %s; %s')
          :format(seed, case, ty[1], ty[2], mtvText(m), show(a, b)))
        assert(m.separating == not want, ('seed %d case %d (%s-%s): S.AT separating = %s but the oracle says %s'
          .. ' (signed distance %.17g); %s; %s'):format(seed, case, ty[1], ty[2], tostring(m.separating),
          want and 'overlap' or 'no overlap', sd, mtvText(m), show(a, b)))
      end
    end
  end
  return case, skipped
end

describe('S.AT properties', function()
  it('SAT verdict agrees with an independent brute-force overlap test', function()
    local cases, skipped = verdictProperty(0, 150, false)
    -- guard against a vacuous property: random pairs are almost never that close
    assert(skipped <= 0.01 * cases, ('seed %d: %d of %d cases skipped as touching'):format(SEED, skipped, cases))
  end)

  -- The same on a small integer grid, where edges share lines, vertices sit on edges and
  -- circle centres sit on edge lines exactly. Many of these pairs touch (skipped).
  it('SAT verdict agrees with the brute-force test on integer-grid shapes (exact alignments)', function()
    local cases, skipped = verdictProperty(1, 60, true)
    assert(skipped <= 0.4 * cases, ('seed %d: %d of %d cases skipped as touching'):format(SEED, skipped, cases))
  end)

  it('depth is exact for circles against polygons and edges', function()
    local seed = SEED -- reported in messages; this property's own stream: SEED + 2
    local rng = PRNG.new(SEED + 2)
    local types = { { 'circle', 'poly' }, { 'poly', 'circle' }, { 'circle', 'edge' }, { 'edge', 'circle' } }
    local case = 0
    for _, ty in ipairs(types) do
      for k = 1, 150 do
        case = case + 1
        local a, b = gen.pair(S, rng, ty[1], ty[2], k % 2 == 0)
        local C, P = a, b
        if ty[1] ~= 'circle' then C, P = b, a end
        local cx, cy = C:getCentroid()
        local r = C:getRadius()
        local dist = brute.pointSignedDist(brute.of(P), cx, cy) -- < 0 inside
        local expected = r - dist
        local m = S.AT(a, b)
        local tol = 1e-9 * (r + abs(dist))
        if expected > tol then
          assert(not m.separating and abs(m.depth - expected) <= tol, ('seed %d case %d (%s-%s): depth %.17g,'
            .. ' expected r - signed distance = %.17g - %.17g = %.17g; %s; %s'):format(seed, case, ty[1], ty[2],
            m.depth, r, dist, expected, mtvText(m), show(a, b)))
        elseif expected < -tol then
          -- separated: MTV.lua documents depth as minus a gap found along some axis, a
          -- lower bound of the true gap -expected
          assert(m.separating and m.depth <= 0 and -m.depth <= -expected + tol, ('seed %d case %d (%s-%s):'
            .. ' separated by %.17g but depth %.17g; %s; %s'):format(seed, case, ty[1], ty[2], -expected, m.depth,
            mtvText(m), show(a, b)))
        end
      end
    end
  end)

  it('moving by the MTV separates the pair, and no sampled shorter move does', function()
    local seed = SEED -- reported in messages; this property's own stream: SEED + 3
    local rng = PRNG.new(SEED + 3)
    local case = 0
    for _, ty in ipairs(PAIR_TYPES) do
      for _ = 1, 40 do
        case = case + 1
        local a, b = gen.pair(S, rng, ty[1], ty[2], true)
        local da = brute.of(a)
        local sd = brute.signedDistance(da, brute.of(b))
        local scale = brute.scale(da, brute.of(b))
        local m = S.AT(a, b)
        local depth = m.depth
        local where = ('seed %d case %d (%s-%s): %s; %s'):format(seed, case, ty[1], ty[2], mtvText(m), show(a, b))
        assert(not m.separating and depth > 0, where)
        -- the vector is the unit normal times the depth
        assert(abs(m.nx * m.nx + m.ny * m.ny - 1) <= 1e-12, 'normal not unit: ' .. where)
        assert(abs(m.x - m.nx * depth) <= 1e-12 * depth and abs(m.y - m.ny * depth) <= 1e-12 * depth,
          'vector is not normal * depth: ' .. where)
        -- exact minimum: the distance from the origin to the Minkowski difference's boundary
        assert(abs(depth + sd) <= 1e-9 * scale, ('depth %.17g, oracle penetration %.17g: %s'):format(depth, -sd, where))
        if depth > 1e-6 * scale then
          local moved = b:copy()
          moved:translate(m.x * (1 + 1e-7) + m.nx * 1e-9, m.y * (1 + 1e-7) + m.ny * 1e-9)
          assert(not brute.overlaps(da, brute.of(moved)), 'still overlapping after moving b by the MTV: ' .. where)
          for k = 1, 16 do
            local t = (k - 1 + rng:next()) * pi / 8
            local dx, dy = cos(t), sin(t)
            local short = b:copy()
            short:translate(dx * depth * 0.999, dy * depth * 0.999)
            assert(brute.overlaps(da, brute.of(short)), ('moving b by 0.999 * depth along (%.17g, %.17g)'
              .. ' separates it, so the MTV is not the minimum: %s'):format(dx, dy, where))
          end
        end
      end
    end
  end)

  -- Mirroring. Depths must agree when colliding (the penetration depth is a property of
  -- the pair). When separating, MTV.lua documents depth as minus the gap found along the
  -- first separating axis met, a lower bound of the true gap that depends on the search
  -- order, so there each side is only checked to be such a lower bound.
  -- Vectors must be exact negatives only when the minimum translation is unique: the
  -- oracle's Minkowski difference has one nearest face, the runner-up farther by more
  -- than 1e-9 times the coordinate scale (with two equally deep faces, or concentric
  -- circles, S.AT(a, b) and S.AT(b, a) may legitimately pick different ones).
  it('S.AT(a, b) and S.AT(b, a) mirror each other', function()
    local seed = SEED -- reported in messages; this property's own stream: SEED + 4
    local rng = PRNG.new(SEED + 4)
    local case, m1, m2 = 0, S.MTV(), S.MTV()
    for _, ty in ipairs(PAIR_TYPES) do
      for k = 1, 120 do
        case = case + 1
        local a, b = gen.pair(S, rng, ty[1], ty[2], k % 2 == 0, k % 10 == 1)
        local da, db = brute.of(a), brute.of(b)
        local sd, runnerUp = brute.signedDistance(da, db)
        local scale = brute.scale(da, db)
        S.AT(a, b, m1)
        S.AT(b, a, m2)
        local where = ('seed %d case %d (%s-%s): S.AT(a, b) %s; S.AT(b, a) %s; %s'):format(seed, case, ty[1], ty[2],
          mtvText(m1), mtvText(m2), show(a, b))
        assert(m1.colliderShape == a and m1.collidedShape == b, 'S.AT(a, b) shapes: ' .. where)
        assert(m2.colliderShape == b and m2.collidedShape == a, 'S.AT(b, a) shapes: ' .. where)
        assert(m1.separating == m2.separating, 'separating differs: ' .. where)
        if not m1.separating then
          assert(abs(m1.depth - m2.depth) <= 1e-12 * max(abs(m1.depth), abs(m2.depth)), 'depth differs: ' .. where)
          if sd < 0 and runnerUp - sd > 1e-9 * scale then
            local tol = 1e-9 * scale
            assert(abs(m1.x + m2.x) <= tol and abs(m1.y + m2.y) <= tol, 'vectors are not opposite: ' .. where)
          end
        elseif sd > 1e-9 * scale then
          local gap = sd
          assert(m1.depth <= 0 and -m1.depth <= gap * (1 + 1e-9), 'S.AT(a, b) gap exceeds the true gap: ' .. where)
          assert(m2.depth <= 0 and -m2.depth <= gap * (1 + 1e-9), 'S.AT(b, a) gap exceeds the true gap: ' .. where)
        end
      end
    end
  end)
end)
