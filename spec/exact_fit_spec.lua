-- Exact fits (docs/moving.md, "Moving bodies in a space", Exact fits): touching is never
-- colliding, for moves too. A move stops half a skin short of a wall, so a body sliding down
-- the wall is that much over the rim of a shaft exactly its size; the move goes on into the
-- shaft shifted across by that much, touching both sides, when nothing overlaps it there.
-- bump.lua's spec "when sliding" and its mirror images (the shaft to the left and to the right,
-- falling and rising), a box along a floor into a hole exactly its width, a circle, a capsule
-- and a rounded rectangle, at scales 1, 10, 100 and 1,000; and the boundary: a shaft narrower
-- than the body by the least amount its coordinates can tell is never entered. Hand-worked
-- cases.
local S = require('strike')
local expect = require('spec.helpers.expect')

local H, T = S.hapes, S.trikers
local near = expect.near

local SCALES = { 1, 10, 100, 1000 }
-- The four mirror images: the shaft to the right (sx = 1) or left, falling (sy = 1, y grows
-- downward) or rising.
local MIRRORS = { { 1, 1 }, { -1, 1 }, { 1, -1 }, { -1, -1 } }

-- The next double above v > 0: v plus its unit in the last place, the least power of two u
-- that v + u still adds exactly.
local function above(v)
  local u = 2 ^ math.ceil(math.log(v) / math.log(2))
  while (v + u / 2) - v == u / 2 do u = u / 2 end
  return v + u
end

-- bump.lua's "when sliding", at scale k, mirrored by (sx, sy): with top-left corners, a = (0,
-- 0, 1, 1) moves to (5, 5); b = (0, 2, 1, 2) and c = (2, 1, 1, 1). Centroids: a (0.5, 0.5), b
-- (0.5, 3), c (2.5, 1.5). a's right face reaches c's left face (x = 2) after 1 of 5 across,
-- t = 0.2, a then at (1.5, 1.5) beside c (both y [1, 2]); it slides down c (half a skin to its
-- left) onto the rim of the shaft x [1, 2] between b (x [0, 1], from y = 2 down) and the
-- line of c: it goes on into the shaft and reaches the goal, its centroid (1.5, 5.5), with c
-- its one collision (bump: (1, 5) and 'c').
local function bumpWorld(k, sx, sy, body)
  local sp = S.pace()
  local a = sp:add(body(0.5 * k * sx, 0.5 * k * sy, k))
  local b = sp:add(H.Rectangle(0.5 * k * sx, 3 * k * sy, k, 2 * k))
  local c = sp:add(H.Rectangle(2.5 * k * sx, 1.5 * k * sy, k, k))
  return sp, a, b, c
end

local function box(x, y, k) return H.Rectangle(x, y, k, k) end

-- The body fits the shaft x [k, 2k] (mirrored): its bounds are exactly the shaft's sides.
local function inShaft(a, k, sx, what)
  local x0, _, x1 = a:getBounds()
  if sx < 0 then x0, x1 = -x1, -x0 end
  assert(x0 == k and x1 == 2 * k, ('%s: the body spans x [%.17g, %.17g], not the shaft [%g, %g]')
    :format(what, x0, x1, k, 2 * k))
end

describe('exact fits', function()
  for _, k in ipairs(SCALES) do
    it(('bump.lua\'s "when sliding": a box slides off a wall into a shaft exactly its width (scale %g)'):format(k),
      function()
        for _, m in ipairs(MIRRORS) do
          local sx, sy = m[1], m[2]
          local what = ('scale %g, mirror (%d, %d)'):format(k, sx, sy)
          local sp, a, b, c = bumpWorld(k, sx, sy, box)
          local x, y, cols, n = sp:move(a, 5.5 * k * sx, 5.5 * k * sy)
          assert.equal(1, n, what)
          assert.equal(c, cols[1].other, what)
          assert.equal('slide', cols[1].type, what)
          near(cols[1].t, 0.2, 1e-12, what .. ': t')
          near(cols[1].nx, -sx, 0, what .. ': nx')
          near(cols[1].ny, 0, 0, what .. ': ny')
          assert.equal(5.5 * k * sy, y, what .. ': y')
          near(x, 1.5 * k * sx, 1e-15 * k, what .. ': x')
          inShaft(a, k, sx, what)
          assert.is_false(S.triking(a, b), what)
          assert.is_false(S.triking(a, c), what)
        end
      end)

    it(('a circle, a capsule and a rounded rectangle slide into the same shaft (scale %g)'):format(k), function()
      -- (the circle r = k/2 meets c as the box does; the capsule k x 2k, its centroid at y = 0,
      -- spans y [-k, k] and meets c at t = 0.2 too, side to side; the rounded rectangle's corners
      -- are quarter circles r = k/4, a whole number of quarters: its extent is exact)
      local bodies = {
        circle = function(x, y) return H.Circle(x, y, k / 2) end,
        capsule = function(x) return H.Capsule(x, 0, k, 2 * k) end,
        rounded = function(x, y) return H.Rectangle(x, y, k, k, 0, k / 4) end,
      }
      for _, name in ipairs({ 'circle', 'capsule', 'rounded' }) do
        for _, m in ipairs(MIRRORS) do
          local sx, sy = m[1], m[2]
          local what = ('%s, scale %g, mirror (%d, %d)'):format(name, k, sx, sy)
          local sp, a, b, c = bumpWorld(k, sx, sy, bodies[name])
          local ax, ay = a:getCentroid()
          local x, y, cols, n = sp:move(a, ax + 5 * k * sx, ay + 5 * k * sy)
          assert.equal(1, n, what)
          assert.equal(c, cols[1].other, what)
          near(cols[1].nx, -sx, 0, what .. ': nx')
          near(cols[1].ny, 0, 0, what .. ': ny')
          near(y, ay + 5 * k * sy, 1e-15 * k, what .. ': y')
          near(x, 1.5 * k * sx, 1e-12 * k, what .. ': x')
          inShaft(a, k, sx, what)
          assert.is_false(S.triking(a, b), what)
          assert.is_false(S.triking(a, c), what)
        end
      end
    end)

    it(('a box sliding along a floor drops into a hole exactly its width, against the wall beyond (scale %g)')
      :format(k), function()
        -- The floor's top is y = 0 (y down) up to the hole x [0, k]; beyond it a wall from
        -- x = k, its top at -4k; the hole's bottom y = 3k. A box k x k on the floor at x = -3.5k
        -- walks right 0.3k a move, falling 0.2k (gravity): it stops against the wall half a skin
        -- short, over the hole but half a skin over the floor's end; the next move falls into
        -- the hole (shifted against the wall) and lands on its bottom: centroid (0.5k, 2.5k),
        -- half a skin above it.
        for _, m in ipairs(MIRRORS) do
          local sx, sy = m[1], m[2]
          local what = ('scale %g, mirror (%d, %d)'):format(k, sx, sy)
          local sp = S.pace()
          local floor = sp:add(H.Rectangle(-5 * k * sx, 0.5 * k * sy, 10 * k, k))
          local wall = sp:add(H.Rectangle(1.5 * k * sx, -0.5 * k * sy, k, 7 * k))
          local bottom = sp:add(H.Rectangle(0.5 * k * sx, 3.5 * k * sy, k, k))
          local a = sp:add(H.Rectangle(-3.5 * k * sx, -0.5 * k * sy, k, k))
          for _ = 1, 40 do
            local x, y = a:getCentroid()
            sp:move(a, x + 0.3 * k * sx, y + 0.2 * k * sy)
          end
          local x, y = a:getCentroid()
          near(x, 0.5 * k * sx, 1e-15 * k, what .. ': x')
          near(y, 2.5 * k * sy, sp.SKIN * a:getRadius(), what .. ': y')
          local x0, _, x1 = a:getBounds()
          if sx < 0 then x0, x1 = -x1, -x0 end
          assert(x0 == 0 and x1 == k, what .. ': the box is not exactly in the hole')
          for _, o in ipairs({ floor, wall, bottom }) do assert.is_false(S.triking(a, o), what) end
        end
      end)

    it(('a shaft narrower than the body by the least amount its coordinates tell is not entered (scale %g)')
      :format(k), function()
        -- bump's world with b moved across by one unit in the last place of 2k (the shaft's far
        -- side; at x in [k, 2k) a unit is half that, and a body's far side rounds to 2k from
        -- half a unit past it): b's right side at k + u, the shaft 2k - (k + u) wide, less than
        -- the box wherever it is put. a stops at b's corner and c, on the rim (y = 1.5k).
        local u = above(2 * k) - 2 * k
        for _, m in ipairs(MIRRORS) do
          local sx, sy = m[1], m[2]
          local what = ('scale %g, mirror (%d, %d)'):format(k, sx, sy)
          local sp = S.pace()
          local a = sp:add(H.Rectangle(0.5 * k * sx, 0.5 * k * sy, k, k))
          local b = sp:add(H.Rectangle((0.5 * k + u) * sx, 3 * k * sy, k, 2 * k))
          local c = sp:add(H.Rectangle(2.5 * k * sx, 1.5 * k * sy, k, k))
          local bx0, _, bx1 = b:getBounds()
          assert.equal(k + u, sx > 0 and bx1 or -bx0) -- (b's side is where it was meant to be)
          local _, y = sp:move(a, 5.5 * k * sx, 5.5 * k * sy)
          near(y, 1.5 * k * sy, sp.SKIN * a:getRadius(), what .. ': y (on the rim)')
          assert.is_false(S.triking(a, b), what)
          assert.is_false(S.triking(a, c), what)
        end
      end)
  end

  it('the shift is at most the skin: over the rim by 0.9 skins a box goes in, by 1.1 it lands', function()
    -- a box 1 x 1 dropped straight down beside the shaft x [1, 2] between b (x [0, 1], y
    -- [2, 4]) and c (x [2, 3], y [1, 6]), its left side 0.9 or 1.1 skins over b's rim: it goes
    -- on down the shaft to y = 5.5 (shifted to x = 1.5), or lands on b (y = 1.5, half a skin
    -- above it)
    for _, over in ipairs({ 0.9, 1.1 }) do
      local sp = S.pace()
      local skin = sp.SKIN * math.sqrt(0.5)
      local a = sp:add(H.Rectangle(1.5 - over * skin, 0.5, 1, 1))
      local b = sp:add(H.Rectangle(0.5, 3, 1, 2))
      local c = sp:add(H.Rectangle(2.5, 3.5, 1, 5))
      local x, y, cols, n = sp:move(a, 1.5 - over * skin, 5.5)
      if over < 1 then
        assert.equal(0, n)
        assert.equal(1.5, x)
        assert.equal(5.5, y)
      else
        assert.equal(1, n)
        assert.equal(b, cols[1].other)
        near(x, 1.5 - over * skin, 0)
        near(y, 1.5, skin)
      end
      assert.is_false(S.triking(a, b))
      assert.is_false(S.triking(a, c))
    end
  end)

  it('a body passed through is no wall: the fit only checks what the move would not pass', function()
    -- bump's world with a thin box across the top of the shaft (x [1, 2], y [1.9, 2.1]), which
    -- the box overlaps where it shifts into the shaft: crossed ('cross'), the box still fits;
    -- solid ('slide'), the box lands on it (y = 1.9 - 0.5)
    for _, solid in ipairs({ false, true }) do
      local sp = S.pace()
      local a = sp:add(H.Rectangle(0.5, 0.5, 1, 1))
      sp:add(H.Rectangle(0.5, 3, 1, 2))
      sp:add(H.Rectangle(2.5, 1.5, 1, 1))
      local lid = sp:add(T.Rectangle(1.5, 2, 1, 0.2))
      local function filter(_, o)
        if o == lid and not solid then return 'cross' end
        return 'slide'
      end
      local _, y = sp:move(a, 5.5, 5.5, filter)
      if solid then near(y, 1.4, 1e-5) else assert.equal(5.5, y) end
      assert.is_false(S.triking(a, lid) and solid)
    end
  end)
end)
