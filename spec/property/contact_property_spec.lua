-- Property specs for S.ite: contact points of random colliding pairs.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local gen = require('spec.property.gen')

local SEED = PRNG.seedFromEnv(4242)
local KINDS = { 'poly', 'circle', 'edge' }

describe('S.ite properties', function()
  it('contact points lie inside both shapes\' slightly inflated bounds, with depth within the MTV\'s', function()
    local rng = PRNG.new(SEED)
    local case = 0
    for _, ka in ipairs(KINDS) do
      for _, kb in ipairs(KINDS) do
        for _ = 1, 120 do
          case = case + 1
          local a, b = gen.pair(S, rng, ka, kb, true, case % 5 == 0)
          local m = S.AT(a, b)
          if not m.separating then
            local c = S.ite(m)
            assert(c and (c.count == 1 or c.count == 2), ('seed %d case %d: no contact for a collision (%s)')
              :format(SEED, case, gen.show(a) .. ' / ' .. gen.show(b)))
            -- midway between the surfaces: at most half the depth outside either shape
            local slack = 1e-9 * (a:getRadius() + b:getRadius() + 1) + m.depth / 2
            for i = 1, c.count do
              local p = c[i]
              for _, s in ipairs({ a, b }) do
                local x0, y0, x1, y1 = s:getBounds()
                assert(p.x >= x0 - slack and p.x <= x1 + slack and p.y >= y0 - slack and p.y <= y1 + slack,
                  ('seed %d case %d: point %d (%.17g, %.17g) outside the bounds of %s'):format(SEED, case, i,
                    p.x, p.y, gen.show(s)))
              end
              assert(p.depth > 0 and p.depth <= m.depth * (1 + 1e-6) + 1e-12,
                ('seed %d case %d: point %d depth %.17g against the MTV\'s %.17g'):format(SEED, case, i,
                  p.depth, m.depth))
              assert(p.depth == p.depth and p.x == p.x and p.y == p.y and type(p.id) == 'number',
                ('seed %d case %d: malformed point %d'):format(SEED, case, i))
            end
          end
        end
      end
    end
  end)
end)
