-- Property-based spec: S.AT does not depend on where the pair is or how it is turned.
-- Reproduce a failure with STRIKE_SEED=<seed> (any VM).
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')
local gen = require('spec.property.gen')

local abs, max, cos, sin, pi = math.abs, math.max, math.cos, math.sin, math.pi

local SEED = PRNG.seedFromEnv(20240611)

local PAIR_TYPES = {
  { 'poly', 'poly' }, { 'circle', 'poly' }, { 'poly', 'circle' }, { 'circle', 'circle' },
  { 'edge', 'poly' }, { 'poly', 'edge' }, { 'edge', 'circle' }, { 'circle', 'edge' }, { 'edge', 'edge' },
}

local function mtvText(m)
  return ('mtv (%.17g, %.17g) depth %.17g separating %s'):format(m.x, m.y, m.depth, tostring(m.separating))
end

describe('S.AT invariance', function()
  -- Both shapes are rotated about one random point by one random angle, then both are
  -- translated by one random vector. Areas must not change (1e-12 relative), nor the
  -- verdict (cases within 1e-7 times the coordinate scale of touching are skipped), nor the
  -- depth (1e-9 relative + 1e-9 absolute; when separating too, since the search order of
  -- the faces, which picks the reported gap, turns with the pair). When the minimum
  -- translation is unique (see the mirror property), the MTV turns with the pair.
  it('rotating and translating both shapes together changes neither areas, verdict nor depth', function()
    local seed = SEED -- reported in messages; this property's own stream: SEED + 10
    local rng = PRNG.new(SEED + 10)
    local case = 0
    for _, ty in ipairs(PAIR_TYPES) do
      for k = 1, 70 do
        case = case + 1
        local a, b = gen.pair(S, rng, ty[1], ty[2], k % 2 == 0)
        local theta = rng:range(-pi, pi)
        local px, py = rng:range(-100, 100), rng:range(-100, 100)
        local dx, dy = rng:range(-100, 100), rng:range(-100, 100)
        local a2, b2 = a:copy(), b:copy()
        a2:rotate(theta, px, py):translate(dx, dy)
        b2:rotate(theta, px, py):translate(dx, dy)
        local where = ('seed %d case %d (%s-%s): rotate(%.17g, %.17g, %.17g), translate(%.17g, %.17g); a = %s; b = %s')
          :format(seed, case, ty[1], ty[2], theta, px, py, dx, dy, gen.show(a), gen.show(b))

        for _, p in ipairs({ { a, a2 }, { b, b2 } }) do
          local before, after = p[1]:getArea(), p[2]:getArea()
          assert(abs(before - after) <= 1e-12 * before, ('area %.17g became %.17g: %s'):format(before, after, where))
        end

        local da, db = brute.of(a), brute.of(b)
        local sd, runnerUp = brute.signedDistance(da, db)
        local scale = max(brute.scale(da, db), brute.scale(brute.of(a2), brute.of(b2)))
        if abs(sd) > 1e-7 * scale then
          local m1, m2 = S.AT(a, b), S.AT(a2, b2)
          local text = ('before %s; after %s; %s'):format(mtvText(m1), mtvText(m2), where)
          assert(m1.separating == m2.separating, 'verdict changed: ' .. text)
          assert(abs(m1.depth - m2.depth) <= 1e-9 * abs(m1.depth) + 1e-9, 'depth changed: ' .. text)
          if not m1.separating and runnerUp - sd > 1e-7 * scale then
            local c, s = cos(theta), sin(theta)
            local rx, ry = c * m1.x - s * m1.y, s * m1.x + c * m1.y
            local tol = 1e-9 * abs(m1.depth) + 1e-9
            assert(abs(rx - m2.x) <= tol and abs(ry - m2.y) <= tol, 'the MTV did not turn with the pair: ' .. text)
          end
        end
      end
    end
  end)
end)
