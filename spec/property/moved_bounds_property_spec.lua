-- A polygon that only moved since its last refresh tells S.pace its bounds without a refresh
-- (VertexShape:_movedBounds): its last bounds, moved, grown by a rounding's worth. Those
-- must hold the bounds a refresh computes (or S.pace could miss a pair whose shapes overlap
-- by a hair), and exceed them by no more than that rounding. Seeded shapes of every polygon
-- kind, rounded ones too, far from the origin and at any scale, moved many times between
-- refreshes. Reproduce a failure with STRIKE_SEED=<seed>.
local S = require('strike')
local PRNG = require('spec.helpers.prng')
local gen = require('spec.property.gen')

local SEED = PRNG.seedFromEnv(20261124)
local CASES = 3000

describe('moved bounds', function()
  it(('hold the refreshed bounds, and exceed them by a rounding at most (%d cases)'):format(CASES), function()
    local rng = PRNG.new(SEED)
    local checked = 0
    for case = 1, CASES do
      local where = ('seed %d case %d'):format(SEED, case)
      local far = gen.logRange(rng, 1, 1e9) * (rng:next() < 0.5 and -1 or 1)
      local kind = gen.polygonKinds[rng:int(1, #gen.polygonKinds)]
      local s = gen.shape(S, rng, kind, far, -far / 3)
      if rng:next() < 0.3 then s = S.hapes.Rectangle(far, far, rng:range(1, 50), rng:range(1, 50), 0.3, 0.5) end
      s:scale(gen.logRange(rng, 1e-3, 1e3))
      s:getBounds() -- (refreshed here)
      for _ = 1, rng:int(1, 20) do
        local step = gen.logRange(rng, 1e-6, 1e6)
        s:translate(rng:range(-step, step), rng:range(-step, step))
      end
      local x0, y0, x1, y1 = s:_movedBounds()
      assert(x0, where .. ': no moved bounds for a shape that only moved')
      local r0, q0, r1, q1 = s:getBounds()
      assert(x0 <= r0 and y0 <= q0 and x1 >= r1 and y1 >= q1, ('%s: moved bounds %.17g %.17g %.17g %.17g do not hold'
        .. ' the refreshed %.17g %.17g %.17g %.17g'):format(where, x0, y0, x1, y1, r0, q0, r1, q1))
      local slack = 1e-12 * (math.abs(r0) + math.abs(q0) + math.abs(r1) + math.abs(q1) + 1e-300)
      assert(r0 - x0 <= slack and q0 - y0 <= slack and x1 - r1 <= slack and y1 - q1 <= slack,
        where .. ': moved bounds exceed the refreshed ones by more than a rounding')
      s:rotate(0.1)
      assert.is_nil(s:_movedBounds(), where .. ': a turned shape must be refreshed')
      checked = checked + 1
    end
    assert.equals(CASES, checked)
  end)
end)
