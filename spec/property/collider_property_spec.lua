-- Property-based specs for colliders: S.triking over random multi-shape colliders, and
-- S.trikers.Concave's convex decomposition of random simple polygons. Reproduce a failure
-- with STRIKE_SEED=<seed> (any VM).
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')
local gen = require('spec.property.gen')

local abs, max, cos, sin, pi = math.abs, math.max, math.cos, math.sin, math.pi

local SEED = PRNG.seedFromEnv(20240611)

-- A Collider of 1..4 random convex shapes (any kind) around (cx, cy).
local function randomCollider(rng, cx, cy)
  local c = S.trikers.Collider()
  for _ = 1, rng:int(1, 4) do
    c:add(gen.shape(S, rng, gen.pick(rng, 'any'), cx + rng:range(-3, 3), cy + rng:range(-3, 3)))
  end
  return c
end

local function showCollider(c)
  local parts = {}
  for s in c:elems() do parts[#parts + 1] = gen.show(s) end
  return '{ ' .. table.concat(parts, ', ') .. ' }'
end

local function leafOf(c, shape)
  for s in c:elems() do
    if s == shape then return true end
  end
  return false
end

describe('collider properties', function()
  -- The reference: S.AT on every leaf pair. Cases where some pair is within 1e-9 (times
  -- the coordinate scale) of touching are skipped: there S.triking's bounding-box
  -- pre-test and S.AT may legitimately round differently.
  it('S.triking agrees with "some leaf pair collides", is at least the deepest pair; S.ettle separates all',
    function()
      local seed = SEED -- reported in messages; this property's own stream: SEED + 20
      local rng = PRNG.new(SEED + 20)
      local skipped = 0
      for case = 1, 300 do
        local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
        local c1 = randomCollider(rng, ox, oy)
        local c2 = randomCollider(rng, ox, oy)
        local d = rng:range(0, 1.2) * (c1:getRadius() + c2:getRadius())
        local t = rng:range(0, 2 * pi)
        c2:translate(d * cos(t), d * sin(t))
        local where = ('seed %d case %d: c1 = %s; c2 = %s'):format(seed, case, showCollider(c1), showCollider(c2))

        assert(S.triking(c1, c1) == false, 'S.triking(c1, c1) is not false: ' .. where)
        assert(S.triking(c2, c2) == false, 'S.triking(c2, c2) is not false: ' .. where)

        local any, deepest, nearTouch, scale = false, 0, false, 1
        for s1 in c1:elems() do
          for s2 in c2:elems() do
            local m = S.AT(s1, s2)
            local sc = brute.scale(brute.of(s1), brute.of(s2))
            scale = max(scale, sc)
            if abs(m.depth) <= 1e-9 * sc then nearTouch = true end
            if not m.separating then
              any = true
              if m.depth > deepest then deepest = m.depth end
            end
          end
        end
        if nearTouch then
          skipped = skipped + 1
        else
          local res = S.triking(c1, c2)
          if not any then
            assert(res == false, 'no leaf pair collides, yet S.triking returned an MTV: ' .. where)
          else
            assert(res, ('a leaf pair collides (deepest %.17g), yet S.triking returned false: %s')
              :format(deepest, where))
            local text = ('S.triking depth %.17g, deepest pair %.17g: %s'):format(res.depth, deepest, where)
            -- (every overlapping pair must be left: the deepest one's depth is a lower bound,
            -- reached when its own push leaves every other pair apart; the minimum itself is
            -- checked against an independent oracle in compound_mtv_property_spec.lua)
            assert(not res.separating and res.depth >= deepest * (1 - 1e-12), 'shorter than the deepest: ' .. text)
            assert(res.collider == c1 and res.collided == c2, 'collider/collided are not c1/c2: ' .. text)
            assert(leafOf(c1, res.colliderShape) and leafOf(c2, res.collidedShape), 'shapes are not leaves: ' .. text)
            if res.edgeIndex ~= 0 then -- (the deepest pair's own MTV)
              local again = S.AT(res.colliderShape, res.collidedShape)
              assert(again.depth == res.depth and again.x == res.x and again.y == res.y,
                'the MTV is not S.AT of its own shapes: ' .. text)
            end
            S.ettle(res)
            for s1 in c1:elems() do
              for s2 in c2:elems() do
                local after = S.AT(s1, s2)
                assert(after.separating or after.depth <= 1e-9 * scale,
                  ('after S.ettle a pair is still %.17g deep: %s'):format(after.depth, text))
              end
            end
          end
        end
      end
    end)

  -- Random simple polygons: star-shaped about their centre (sorted random angles, random
  -- radii), n = 5..40, random scale (0.01..1000) and offset, either winding.
  it('S.trikers.Concave tiles random simple polygons with convex pieces', function()
    local seed = SEED -- reported in messages; this property's own stream: SEED + 21
    local rng = PRNG.new(SEED + 21)
    for case = 1, 120 do
      local n = rng:int(5, 40)
      local R = gen.logRange(rng, 0.01, 1000)
      local ox, oy = rng:range(-1000, 1000), rng:range(-1000, 1000)
      local angles = gen.starAngles(rng, n) -- (each edge a chord of its own sector: simple)
      local xs, ys, flat = {}, {}, {}
      local reverse = rng:next() < 0.5
      for i = 1, n do
        local k = reverse and n + 1 - i or i
        local r = R * rng:range(0.2, 1)
        xs[k], ys[k] = ox + r * cos(angles[i]), oy + r * sin(angles[i])
      end
      for i = 1, n do flat[2 * i - 1], flat[2 * i] = xs[i], ys[i] end
      local outline = abs(brute.shoelace(xs, ys, n))
      local parts = {}
      for i = 1, 2 * n do parts[i] = ('%.17g'):format(flat[i]) end
      local where = ('seed %d case %d: S.trikers.Concave(%s)'):format(seed, case, table.concat(parts, ', '))

      local ok, c = pcall(S.trikers.Concave, flat)
      assert(ok, ('Concave failed on a simple polygon (%s): %s'):format(tostring(c), where))

      local sum, pieces = 0, {}
      for piece in c:elems() do
        pieces[#pieces + 1] = piece
        local v, m = piece:getVertices()
        assert(m >= 3, ('a piece has %d vertices: %s'):format(m, where))
        local px, py = {}, {}
        for i = 1, m do px[i], py[i] = v[2 * i - 1], v[2 * i] end
        local area = brute.shoelace(px, py, m)
        local sign = area < 0 and -1 or 1
        for i = 1, m do
          local j, l = i % m + 1, (i + 1) % m + 1
          local turn = sign * brute.cross(px[i], py[i], px[j], py[j], px[l], py[l])
          assert(turn > 0, ('piece %d is not strictly convex at vertex %d (turn %.17g): %s'):format(#pieces, j, turn,
            where))
        end
        sum = sum + abs(area)
      end
      assert(abs(sum - outline) <= 1e-9 * outline,
        ('pieces cover %.17g, the outline %.17g: %s'):format(sum, outline, where))
      assert(abs(c:getArea() - outline) <= 1e-9 * outline,
        ('getArea %.17g, the outline %.17g: %s'):format(c:getArea(), outline, where))

      -- sample points of the bounding box away from the outline: inside ones lie in
      -- exactly one piece, outside ones in none
      local x0, y0, w, h = c:getBbox()
      local inside, tries = 0, 0
      while inside < 20 and tries < 2000 do
        tries = tries + 1
        local x, y = x0 + w * rng:next(), y0 + h * rng:next()
        if brute.outlineDist(xs, ys, n, x, y) > 1e-6 * R then
          local count = 0
          for i = 1, #pieces do
            if pieces[i]:containsPoint(x, y) then count = count + 1 end
          end
          local isIn = brute.insideSimple(xs, ys, n, x, y)
          if isIn then inside = inside + 1 end
          assert(count == (isIn and 1 or 0), ('point (%.17g, %.17g) %s the outline is in %d pieces: %s')
            :format(x, y, isIn and 'inside' or 'outside', count, where))
        end
      end
      assert(inside == 20, 'could not sample 20 interior points: ' .. where)
    end
  end)
end)
