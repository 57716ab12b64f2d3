-- The range of motion and the skin (README, "Conventions", Motion and Sizes; docs/moving.md,
-- "Moving bodies in a space"; strike/limits.lua): a move stops half a skin short of what it
-- meets, the skin a millionth of the moving body's radius wherever it is; sweeps, casts and
-- moves are right within limits.REACH radii of the origin and refused beyond, at the caller's
-- line, exactly at the limit; the precision of a sweep is the moving body's own (a tiny body
-- against a huge one). Regression specs for the numbers of issue 20: at 1e9 a move stopped a
-- whole unit short, moves of 1e11 and more ended inside walls, tunnelled or never started, and
-- S.weep of a tiny body against a huge one answered t = 0 or missed. Hand-worked cases.
local S = require('strike')
local expect = require('spec.helpers.expect')
local limits = require('strike.limits')

local H, T = S.hapes, S.trikers
local near, raisesAt = expect.near, expect.raisesAt
local sqrt = math.sqrt

local SKIN = 1e-6

-- The next double above v > 0, and below: v plus or minus its unit in the last place (the
-- least power of two that v + u still adds exactly).
local function ulp(v)
  local u = 2 ^ math.ceil(math.log(v) / math.log(2))
  while (v + u / 2) - v == u / 2 do u = u / 2 end
  return u
end
local function above(v) return v + ulp(v) end

-- The gap between a body that stopped moving right and the wall whose left face is x = face.
local function stopGap(box, face)
  local _, _, x1 = box:getBounds()
  return face - x1
end

describe('the skin', function()
  it('is a millionth of the radius, and a stop leaves half of it, wherever the body is', function()
    -- A box 200 x 200 (radius 100 sqrt 2) moving right by 1000 toward a wall whose left face
    -- is 500 ahead of its centroid (400 from its right side): it stops half a skin short,
    -- 100 sqrt 2 * 1e-6 / 2, within the rounding of its coordinates (a few units in the last
    -- place of 1e9, 1.2e-7, against the skin 1.4e-4), at the origin, at 1e6 and at 1e9 (where
    -- it stopped a whole unit short: the skin grew by 1e-9 of the distance from the origin).
    local sp0 = S.pace()
    assert.equal(SKIN, sp0.SKIN)
    assert.equal(1e7, sp0.REACH)
    assert.equal(limits.REACH, sp0.REACH)
    local skin = SKIN * 100 * sqrt(2)
    for _, at in ipairs({ 0, 1e6, 1e9, -1e9 }) do
      local sp = S.pace()
      local wall = sp:add(H.Rectangle(at + 550, 0, 100, 2000))
      local box = sp:add(H.Rectangle(at, 0, 200, 200))
      near(box:getRadius(), 100 * sqrt(2), 1e-12)
      local x, _, cols, n = sp:move(box, at + 1000, 0)
      assert.equal(1, n)
      assert.equal(wall, cols[1].other)
      local gap = stopGap(box, at + 500)
      assert(gap > 0 and gap <= skin, ('at %g: the gap %.17g is not in (0, %.17g]'):format(at, gap, skin))
      near(gap, skin / 2, 4 * ulp(math.abs(at) + 1000), ('at %g: the gap'):format(at))
      near(x, at + 400 - skin / 2, 1e-6, 'x')
      assert.is_false(S.triking(box, wall))
    end
  end)

  it('against a tilted wall at 1e9, the stop is within the skin along the normal', function()
    -- the wall turned by 0.3 rad: the box meets one of its faces; it stops apart from it, and
    -- no farther than half a skin over the cosine of the move with the normal
    for _, at in ipairs({ 0, 1e9 }) do
      local sp = S.pace()
      local wall = sp:add(H.Rectangle(at + 700, 0, 100, 2000, 0.3))
      local box = sp:add(H.Rectangle(at, 0, 200, 200))
      local _, _, cols, n = sp:move(box, at + 1000, 0, function() return 'touch' end)
      assert.equal(1, n)
      local dn = -(1000 * cols[1].nx)
      assert(dn > 0)
      local d = S.eparation(box, wall)
      local skin = SKIN * box:getRadius()
      assert(d >= 0 and d <= skin * 1000 / dn, ('at %g: the stop is %.17g from the wall'):format(at, d))
      assert.is_false(S.triking(box, wall))
    end
  end)
end)

describe('the range of motion', function()
  local R = 1e7 -- limits.REACH

  it('at 1e9, a 10 x 10 box (radius 7.07) is out of it: a clear error, not a stop a unit short', function()
    local sp = S.pace()
    sp:add(H.Rectangle(1e9 + 50, 0, 10, 200))
    local box = sp:add(H.Rectangle(1e9, 0, 10, 10))
    raisesAt(function() sp:move(box, 1e9 + 100, 0) end,
      'strike.Space:move: out of the range of motion: the centroid would be 1000000100 from the origin along an'
      .. ' axis, more than 9999999 (limits.REACH - 1) times the size of the body that moves (its radius,'
      .. ' 7.0710678118654')
    raisesAt(function() sp:cast(box, 100, 0) end, 'strike.Space:cast: out of the range of motion')
    raisesAt(function() S.weep(box, 100, 0, H.Circle(0, 0, 1)) end, 'strike.weep: out of the range of motion')
    local x = box:getCentroid()
    assert.equal(1e9, x) -- (refused: the box did not move)
  end)

  it('moves of 1e11: out of it for a small body, right for a body large enough', function()
    -- a box 10 x 10 moving 1e11 is refused; a box 2e4 x 2e4 (radius 14142, 1e11 is 7.1e6 of
    -- it) moving 1e11 toward a wall 1000 thick at 5e10 stops half a skin (0.0071) short of it,
    -- where the old skin (1e-9 of the distance from the origin) left 50; and a body at 1e11
    -- moving 1000 toward a wall 500 ahead of it stops half a skin short, where it stopped 100
    -- short (which, for a move of less than that, was never starting)
    local sp = S.pace()
    local small = sp:add(H.Rectangle(0, 0, 10, 10))
    raisesAt(function() sp:move(small, 1e11, 0) end, 'strike.Space:move: out of the range of motion: the centroid'
      .. ' would be 100000000000 from the origin')
    local skin = SKIN * 1e4 * sqrt(2)
    for _, case in ipairs({ { 0, 1e11, 5e10 + 1e4 }, { 1e11, 1e11 + 1000, 1e11 + 1e4 + 500 } }) do
      sp = S.pace()
      local wall = sp:add(H.Rectangle(case[3] + 500, 0, 1000, 1e5))
      local big = sp:add(H.Rectangle(case[1], 0, 2e4, 2e4))
      sp:move(big, case[2], 0)
      local gap = stopGap(big, case[3])
      assert(gap > 0 and gap <= skin, ('from %g: the gap %.17g is not in (0, %.17g]'):format(case[1], gap, skin))
      assert.is_false(S.triking(big, wall))
    end
  end)

  it('moves inside it never tunnel: a circle of radius 1 at up to 5e6 a move through a wall 1 thick', function()
    for _, at in ipairs({ 0, 4e6, -4e6 }) do
      for _, speed in ipairs({ 1e3, 1e5, 4e6 }) do
        local sp = S.pace()
        local wall = sp:add(H.Rectangle(at + 0.5, 0, 1, 100))
        local c = sp:add(H.Circle(at - speed / 2, 3, 1))
        local x = sp:move(c, at + speed / 2, 3)
        assert(x < at - 1, ('at %g, %g a move: the circle got to %.17g'):format(at, speed, x))
        assert.is_false(S.triking(c, wall))
        near(x, at - 1, SKIN, 'x')
      end
    end
  end)

  describe('errors exactly at the limit', function()
    -- A circle of radius 1 at the origin: its centroid may go R - 1 from the origin along an
    -- axis (all of it then within R): a move by R - 1 is allowed, by the next double after
    -- R - 1 refused.
    local far = H.Rectangle(0, 1e3, 10, 10)

    it('S.weep, along x and y, both ways', function()
      local c = H.Circle(0, 0, 1)
      for _, d in ipairs({ { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } }) do
        S.weep(c, d[1] * (R - 1), d[2] * (R - 1), far)
        local v = above(R - 1)
        raisesAt(function() S.weep(c, d[1] * v, d[2] * v, far) end,
          'strike.weep: out of the range of motion: the centroid would be 9999999.0000000019 from the origin along'
          .. ' an axis, more than 9999999 (limits.REACH - 1) times the size of the body that moves (its radius, 1)')
      end
      -- (turning: the same)
      S.weep(c, R - 1, 0, far, 1)
      raisesAt(function() S.weep(c, above(R - 1), 0, far, 1) end, 'strike.weep: out of the range of motion')
    end)

    it('Space:cast and Space:move', function()
      local sp = S.pace()
      sp:add(far)
      local c = sp:add(H.Circle(0, 0, 1))
      local loose = H.Circle(0, 0, 1)
      for _, body in ipairs({ c, loose }) do
        sp:cast(body, R - 1, 0)
        sp:cast(body, 0, -(R - 1))
        raisesAt(function() sp:cast(body, above(R - 1), 0) end, 'strike.Space:cast: out of the range of motion')
        raisesAt(function() sp:cast(body, 0, -above(R - 1)) end, 'strike.Space:cast: out of the range of motion')
      end
      sp:move(c, R - 1, 0)
      assert.equal(R - 1, c:getCentroid())
      c:translateTo(0, 0)
      raisesAt(function() sp:move(c, above(R - 1), 0) end, 'strike.Space:move: out of the range of motion: the'
        .. ' centroid would be 9999999.0000000019')
      assert.equal(0, c:getCentroid()) -- (refused: nothing moved)
      -- a body already beyond the limit cannot move at all; within, it may move back
      c:translateTo(above(R - 1), 0)
      raisesAt(function() sp:move(c, 0, 0) end, 'strike.Space:move: out of the range of motion')
      raisesAt(function() sp:cast(c, 0, 0) end, 'strike.Space:cast: out of the range of motion')
    end)

    it('a point has no radius: its size is the length of its move', function()
      -- a point at x = R - 2 moving by 1 ends R - 1 from the origin, R - 1 times 1: allowed;
      -- from one double further out, refused; a point that does not move has no size and is no
      -- motion
      local sp = S.pace()
      local p = sp:add(H.Point(R - 2, 0))
      sp:cast(p, 1, 0)
      S.weep(p, 1, 0, far)
      sp:move(p, R - 1, 0)
      p:translateTo(above(R - 2), 0)
      raisesAt(function() sp:move(p, above(R - 2) + 1, 0) end, 'strike.Space:move: out of the range of motion: the'
        .. ' centroid would be 9999999.0000000019 from the origin along an axis, more than 9999999 (limits.REACH - 1)'
        .. ' times the size of the body that moves (it has no radius: the length of its move, 1)')
      assert.is_false(S.weep(H.Point(1e300, 0), 0, 0, far))
      sp:move(p, above(R - 2), 0) -- (no motion)
    end)
  end)
end)

describe('touching within round-off', function()
  it('a body over a face by one unit in the last place does not slide past it into the body', function()
    -- the wall x [1, 2], y [0, 1]; a box 1 x 1 above it, y [-3, -2], its right side at 1 + u
    -- (u = 2^-52, one unit in the last place of 1): it overlaps the wall's side by u across. Moving
    -- down by 4 it meets the wall's top after 2, t = 0.5, normal (0, -1): a tolerance let it
    -- slide down past the wall's side (within round-off of it) and end inside the wall by u.
    -- Level with the side (u = 0), it passes, touching. A move makes it an exact fit: over the
    -- side by less than the skin, it goes on shifted off it by u, and passes, touching.
    local u = 2 ^ -52
    local wall = H.Rectangle(1.5, 0.5, 1, 1)
    local box = H.Rectangle(0.5 + u, -2.5, 1, 1)
    assert.equal(1 + u, select(3, box:getBounds()))
    local h = S.weep(box, 0, 4, wall)
    near(h.t, 0.5, 1e-15)
    assert.equal(0, h.nx)
    assert.equal(-1, h.ny)
    local sp = S.pace()
    sp:add(wall)
    sp:add(box)
    local x, y = sp:move(box, 0.5 + u, 1.5)
    assert.equal(0.5, x)
    assert.equal(1.5, y)
    assert.equal(1, select(3, box:getBounds()))
    assert.is_false(S.triking(box, wall))
    -- level with it: no hit, and it ends beside it, touching
    local level = H.Rectangle(0.5, -2.5, 1, 1)
    assert.is_false(S.weep(level, 0, 4, wall))
    sp = S.pace()
    sp:add(H.Rectangle(1.5, 0.5, 1, 1))
    sp:add(level)
    local _, y2, _, n = sp:move(level, 0.5, 1.5)
    assert.equal(0, n)
    assert.equal(1.5, y2)
    assert.is_false(S.triking(level, wall))
  end)

  it('a box resting on a tilted face and sliding along it is no hit, at 200 angles', function()
    -- a box 4 x 4 turned as the wall 100 x 20 is, put on the wall's upper face (centroid 2 out
    -- along its normal from the face's middle), moved 10 along the face: touching, within the
    -- rounding of their coordinates, and moving along. The move's direction is along the face
    -- only to its rounding, 1e-17: a tolerance on that face's h made it a hit at t = 0 (30 of
    -- these 200), which left a body sliding along a tilted face it touches stuck there.
    local hits, tried = 0, 0
    for i = 1, 200 do
      local a = 0.1 + i * 0.007
      local wall = H.Rectangle(0, 0, 100, 20, a)
      local f, nx, ny = 1, wall:getNormal(1)
      for g = 2, 4 do
        local gx, gy = wall:getNormal(g)
        if gy < ny then f, nx, ny = g, gx, gy end
      end
      local ax, ay = wall:getVertex(f)
      local bx, by = wall:getVertex(f % 4 + 1)
      local box = H.Rectangle((ax + bx) / 2 + nx * 2, (ay + by) / 2 + ny * 2, 4, 4, a)
      if not S.triking(box, wall) then
        tried = tried + 1
        if S.weep(box, -ny * 10, nx * 10, wall) then hits = hits + 1 end
        -- (into the face by a sine of 1e-12, far beyond the rounding of a direction: a hit at 0)
        local h = S.weep(box, -ny * 10 - nx * 1e-11, nx * 10 - ny * 1e-11, wall)
        assert(h and h.t == 0, ('angle %.3f: moving into the face it touches is a hit at t = 0'):format(a))
      end
    end
    assert(tried > 100, 'only ' .. tried .. ' boxes rest apart from their wall')
    assert.equal(0, hits)
  end)
end)

describe('S.weep of a tiny body against a huge one', function()
  -- Sizes are powers of two, so that every side is where it is meant to be: e = 2^-20
  -- (9.5e-7), the huge body 2^20 (1e6) and more across: 1e12 times the tiny one. The tiny
  -- body's precision is its own: before, the tolerance was 1e-11 of the huge body's
  -- coordinates, more than the tiny body, and a sweep found it touching (t = 0) or missed.
  local e = 2 ^ -20
  local big = H.Rectangle(2 ^ 19, 0, 2 ^ 20, 2 ^ 20) -- x [0, 2^20]

  it('meets the near face at the right time', function()
    -- a box e x e with its right side at -e/2, moving right by 2e: t = (e/2) / 2e = 0.25,
    -- normal (-1, 0), at x = 0; a circle of radius e/2 alike
    local h = S.weep(H.Rectangle(-e, 0, e, e), 2 * e, 0, big)
    near(h.t, 0.25, 1e-12)
    assert.equal(-1, h.nx)
    assert.equal(0, h.ny)
    assert.equal(0, h.x)
    h = S.weep(H.Circle(-e, 0, e / 2), 2 * e, 0, big)
    near(h.t, 0.25, 1e-12)
    assert.equal(-1, h.nx)
    assert.equal(0, h.ny)
    -- (at y = 0.3 e, the closest point on the face, from its ends half a million away, is off
    -- by their rounding, 6e-11, which tilted a normal taken from it by 1e-4: the face's own)
    h = S.weep(H.Circle(-e, 0.3 * e, e / 2), 2 * e, 0, big)
    near(h.t, 0.25, 1e-9)
    assert.equal(-1, h.nx)
    assert.equal(0, h.ny)
    -- the huge body moved against the tiny one: the same, the normal turned
    h = S.weep(big, -2 * e, 0, H.Rectangle(-e, 0, e, e))
    near(h.t, 0.25, 1e-12)
    assert.equal(1, h.nx)
  end)

  it('near the huge body\'s corner, the face\'s normal exactly', function()
    -- the huge box x [0, 2^20], y [0, 2^20]; the circle's centre e above its top-left corner's
    -- level: it meets the left face inside, normal (-1, 0) (it was tilted by 7.6e-6)
    local corner = H.Rectangle(2 ^ 19, 2 ^ 19, 2 ^ 20, 2 ^ 20)
    local h = S.weep(H.Circle(-e, e, e / 2), 2 * e, 0, corner)
    near(h.t, 0.25, 1e-12)
    assert.equal(-1, h.nx)
    assert.equal(0, h.ny)
  end)

  it('a thin huge strip, an edge and a chain from above: hit, not missed', function()
    -- the strip y [0, e/2], 2^21 long; a box e x e above, its bottom at -e/2, moving down 2e:
    -- t = 0.25, normal (0, -1)
    for _, b in ipairs({ H.Rectangle(0, e / 4, 2 ^ 21, e / 2), H.Edge(-2 ^ 20, 0, 2 ^ 20, 0),
      T.Chain(-2 ^ 20, 0, 2 ^ 20, 0) }) do
      local h = S.weep(H.Rectangle(0, -e, e, e), 0, 2 * e, b)
      near(h.t, 0.25, 1e-12)
      assert.equal(0, h.nx)
      assert.equal(-1, h.ny)
      h = S.weep(H.Circle(0, -e, e / 2), 0, 2 * e, b)
      near(h.t, 0.25, 1e-12)
      assert.equal(-1, h.ny)
    end
  end)

  it('a tilted huge face: its normal, at the right time', function()
    -- a square 2^21 across turned by 0.3 rad, moved so that the middle of its first face is
    -- at about the origin; the circle 1.5 e in front of that middle moves 2e into it: t 0.5
    -- (it was t = 0, with a normal 1.6e-4 off)
    local tilted = H.Rectangle(0, 0, 2 ^ 21, 2 ^ 21, 0.3)
    local nx, ny = tilted:getNormal(1)
    tilted:translate(-nx * 2 ^ 20, -ny * 2 ^ 20)
    local ax, ay = tilted:getVertex(1)
    local bx, by = tilted:getVertex(2)
    local px, py = (ax + bx) / 2 + nx * 1.5 * e, (ay + by) / 2 + ny * 1.5 * e
    local h = S.weep(H.Circle(px, py, e / 2), -nx * 2 * e, -ny * 2 * e, tilted)
    -- (the face is where its corners' coordinates put it, to a unit in their last place, 2^-32:
    -- 6e-5 of the move)
    near(h.t, 0.5, 1e-4)
    near(h.nx, nx, 1e-12)
    near(h.ny, ny, 1e-12)
  end)

  it('sliding along the huge face it touches is no hit', function()
    -- the box e x e with its right side on x = 0, moving along y: touching, never overlapping
    assert.is_false(S.weep(H.Rectangle(-e / 2, 0, e, e), 0, 3 * e, big))
  end)
end)
