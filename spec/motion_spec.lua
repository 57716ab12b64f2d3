-- S.weep (time of impact of a moving body against a still one) and S.eparation (distance
-- and closest points). Hand-worked cases only: every expected number is derived in the
-- comment beside it, never computed by strike; random cases against a brute-force oracle
-- are in spec/property/sweep_property_spec.lua.
--
-- Reminders (strike/motion/sweep.lua): a hit is {t, x, y, nx, ny, overlapping}, t the
-- fraction of the move at the first touch, (nx, ny) the unit normal from b (still) toward
-- a (moving). Rectangle(cx, cy, w, h) is centred: Rectangle(0, 0, 10, 10) spans x and y in
-- [-5, 5]. With LÖVE, y grows downward.
local S = require('strike')
local expect = require('spec.helpers.expect')
local alloc = require('spec.helpers.alloc')
local sweepModule = require('strike.motion.sweep')

local H, T = S.hapes, S.trikers
local near, raisesAt = expect.near, expect.raisesAt
local sqrt, abs, asin, atan, pi = math.sqrt, math.abs, math.asin, math.atan, math.pi

local TOL = 1e-12

-- S.weep, checking what every answer must be: false, or a table (`out` itself when given)
-- with t in [0, 1], a unit normal, finite numbers and a boolean `overlapping`.
local function weep(a, dx, dy, b, angle, out)
  local h = S.weep(a, dx, dy, b, angle, out)
  if h == false then return false end
  assert.is_table(h)
  if out ~= nil then assert.equals(out, h) end
  for _, k in ipairs({ 't', 'x', 'y', 'nx', 'ny' }) do
    assert(type(h[k]) == 'number' and h[k] == h[k] and abs(h[k]) < math.huge, 'hit.' .. k .. ' must be finite')
  end
  assert(h.t >= 0 and h.t <= 1, ('t = %.17g is outside [0, 1]'):format(h.t))
  near(h.nx * h.nx + h.ny * h.ny, 1, 1e-12, 'squared length of the normal')
  assert.is_boolean(h.overlapping)
  return h
end

-- The hit `h` is (t, x, y, nx, ny) within `tol` (default TOL), not overlapping unless told.
local function isHit(h, t, x, y, nx, ny, tol, overlapping)
  assert(h, 'expected a hit, got false')
  tol = tol or TOL
  near(h.t, t, tol, 't')
  if x then near(h.x, x, tol, 'x') end
  if y then near(h.y, y, tol, 'y') end
  near(h.nx, nx, tol, 'nx')
  near(h.ny, ny, tol, 'ny')
  assert.equals(overlapping or false, h.overlapping)
end

-- `h` must be false (no hit); otherwise the message shows the hit it got.
local function isMiss(h, what)
  if h == false then return end
  assert(false, ('%s: expected no hit, got t = %.17g at (%.17g, %.17g), normal (%.17g, %.17g), overlapping = %s')
    :format(what, h.t, h.x, h.y, h.nx, h.ny, tostring(h.overlapping)))
end

describe('S.weep', function()
  describe('exact times of impact', function()
    it('box against box, head on: t, normal, and the middle of the touching overlap', function()
      -- a spans x [-5, 5], y [-5, 5]; b spans x [25, 35], y [-3, 7]. Moving by (40, 0), a's
      -- right face (x = 5) meets b's left face (x = 25) after 20 of 40: t = 0.5. The normal
      -- from b toward a is (-1, 0). At t = 0.5 the faces share y in [-5, 5] n [-3, 7] =
      -- [-3, 5], whose middle is y = 1: the point is (25, 1).
      local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(30, 2, 10, 10)
      isHit(weep(a, 40, 0, b), 0.5, 25, 1, -1, 0)
      -- The same meeting seen from b moving by (-40, 0) against a: the same t, the opposite
      -- normal (1, 0), and the point shifted by -t (dx, dy) = (20, 0): (5, 1).
      isHit(weep(b, -40, 0, a), 0.5, 5, 1, 1, 0)
      -- Vertically: a moving by (0, 40) toward c (x [-2, 8], y [20, 24]): gap 20 - 5 = 15,
      -- t = 15 / 40 = 0.375; normal (0, -1); shared x [-2, 5], middle 1.5; point (1.5, 20).
      local c = H.Rectangle(3, 22, 10, 4)
      isHit(weep(a, 0, 40, c), 0.375, 1.5, 20, 0, -1)
    end)

    it('circle against a box face', function()
      -- Circle r = 2 at the origin (lowest point y = 2); the box spans x [-5, 5], y [18, 22].
      -- Moving by (0, 32) the circle's bottom reaches y = 18 after 16: t = 16 / 32 = 0.5,
      -- normal (0, -1), point (0, 18) (the circle's centre is then (0, 16)).
      local c, box = H.Circle(0, 0, 2), H.Rectangle(0, 20, 10, 4)
      isHit(weep(c, 0, 32, box), 0.5, 0, 18, 0, -1)
      -- Off-centre, still over the face: from (4, 0) the path x = 4 stays inside [-5, 5].
      isHit(weep(H.Circle(4, 0, 2), 0, 32, box), 0.5, 4, 18, 0, -1)
    end)

    it('circle against a box corner: t from the quadratic', function()
      -- Box x [0, 10], y [0, 10]; its corner (0, 10). Circle r = 5 from (-10, 13) moving by
      -- (20, 0): its centre runs along y = 13, 3 past the box's side y = 10, so no face is met
      -- (the face x = 0 needs the centre's y in [0, 10]; the face y = 10 needs x in [0, 10],
      -- and the corner comes first). It touches the corner when
      --   |(-10 + 20 t, 13) - (0, 10)|^2 = 25  =>  (20 t - 10)^2 + 9 = 25  =>  20 t - 10 = -4
      -- so t = 6 / 20 = 0.3, the centre then at (-4, 13). The normal is (centre - corner) / 5
      -- = (-4, 3) / 5 = (-0.8, 0.6); the point is the corner (0, 10).
      local box = H.Rectangle(5, 5, 10, 10)
      isHit(weep(H.Circle(-10, 13, 5), 20, 0, box), 0.3, 0, 10, -0.8, 0.6, 1e-12)
      -- Along a diagonal onto the corner (10, 0): from (17, -9) by (-10, 10) (centre
      -- (17 - 10 t, -9 + 10 t)): |(7 - 10 t, -9 + 10 t)|^2 = 25
      --   => 200 t^2 - 320 t + 130 - 25 = 0 => 200 t^2 - 320 t + 105 = 0
      --   => t = (320 - sqrt(320^2 - 4 * 200 * 105)) / 400 = (320 - sqrt(18400)) / 400
      -- Centre then (17 - 10 t, -9 + 10 t); normal (centre - (10, 0)) / 5; point (10, 0).
      -- (At that t the centre is at x = 13.39 > 10 and y = -3.39 < 0: the corner region.)
      local t = (320 - sqrt(18400)) / 400
      local cx, cy = 17 - 10 * t, -9 + 10 * t
      isHit(weep(H.Circle(17, -9, 5), -10, 10, box), t, 10, 0, (cx - 10) / 5, cy / 5, 1e-12)
    end)

    it('capsule against an edge', function()
      -- Capsule(0, 0, 4, 10): caps radius 2, core (0, -3)-(0, 3), lowest point y = 5. The
      -- edge y = 15 is 10 below: moving by (0, 20), t = 10 / 20 = 0.5, normal (0, -1), point
      -- (0, 15) below the lower cap.
      local cap = H.Capsule(0, 0, 4, 10)
      isHit(weep(cap, 0, 20, H.Edge(-10, 15, 10, 15)), 0.5, 0, 15, 0, -1)
      -- A slanted edge on the line x + y = 20, from (0, 20) to (20, 0). The core end nearest
      -- it is (0, 3) (x + y = 3, the smallest gap); moving by (10, 10) it is at
      -- (10 t, 3 + 10 t), whose distance to the line is (20 - 3 - 20 t) / sqrt(2). It reaches
      -- the caps' radius 2 when 17 - 20 t = 2 sqrt(2): t = (17 - 2 sqrt(2)) / 20. The foot of
      -- the core end on the line is the point: x + y = 20 - 2 sqrt(2) there, so the foot is
      -- the end plus sqrt(2) (1, 1) = (10 t + sqrt(2), 3 + 10 t + sqrt(2)) = (8.5, 11.5),
      -- inside the edge. Normal from the edge toward the capsule: (-1, -1) / sqrt(2).
      local r2 = 1 / sqrt(2)
      isHit(weep(cap, 10, 10, H.Edge(0, 20, 20, 0)), (17 - 2 * sqrt(2)) / 20, 8.5, 11.5, -r2, -r2, 1e-12)
    end)

    it('point against a rectangle', function()
      -- Point (0, 0) by (16, 0) toward x [8, 12], y [-2, 2]: t = 8 / 16 = 0.5, normal
      -- (-1, 0), point (8, 0).
      isHit(weep(H.Point(0, 0), 16, 0, H.Rectangle(10, 0, 4, 4)), 0.5, 8, 0, -1, 0)
      -- Diagonally by (10, 5) toward x [8, 12], y [-5, 15]: x = 8 at t = 0.8, where y = 4.
      isHit(weep(H.Point(0, 0), 10, 5, H.Rectangle(10, 5, 4, 20)), 0.8, 8, 4, -1, 0)
      -- A point never overlaps by grazing a corner: (0, -2) by (16, 0) runs along the box's
      -- side y = -2 and only touches it.
      assert.is_false(weep(H.Point(0, -2), 16, 0, H.Rectangle(10, 0, 4, 4)))
    end)

    it('rounded rectangle against a circle, on a face and on a rounded corner', function()
      -- Rectangle(0, 0, 10, 10, 0, 2): core x, y in [-3, 3] grown by 2, so it still spans
      -- [-5, 5]. Face: circle r = 3 at (20, 0), its left point x = 17; moving by (20, 0) the
      -- right side x = 5 gets there after 12: t = 0.6, normal (-1, 0), point (17, 0).
      local rr = H.Rectangle(0, 0, 10, 10, 0, 2)
      isHit(weep(rr, 20, 0, H.Circle(20, 0, 3)), 0.6, 17, 0, -1, 0)
      -- Corner: circle r = 3 at (20, 6). The centre's y = 6 is past the core's y in [-3, 3],
      -- so the core corner (3, 3) leads: touching at distance 2 + 3 = 5 with dy = 6 - 3 = 3
      -- means dx = 4: the core corner at (16, 3), moved by 13 of 20: t = 0.65. Normal from
      -- the circle's centre toward the core corner: (16 - 20, 3 - 6) / 5 = (-0.8, -0.6);
      -- the point on the circle: (20, 6) + 3 (-0.8, -0.6) = (17.6, 4.2).
      isHit(weep(rr, 20, 0, H.Circle(20, 6, 3)), 0.65, 17.6, 4.2, -0.8, -0.6, 1e-12)
    end)

    it('diagonal moves', function()
      -- a spans [-1, 1] both ways; b spans x [8, 12], y [8, 12]. Moving by (12, 9): x
      -- overlaps from t = 7 / 12, y from t = 7 / 9; they overlap when both do: t = 7 / 9,
      -- through b's face y = 8 (normal (0, -1)). a's x is then [-1, 1] + 12 * 7 / 9 =
      -- [25 / 3, 31 / 3], inside [8, 12]: the point is (28 / 3, 8).
      local a = H.Rectangle(0, 0, 2, 2)
      isHit(weep(a, 12, 9, H.Rectangle(10, 10, 4, 4)), 7 / 9, 28 / 3, 8, 0, -1, 1e-12)
      -- The same with y and x swapped (by (9, 12)): t = 7 / 9 through the face x = 8,
      -- normal (-1, 0), point (8, 28 / 3).
      isHit(weep(a, 9, 12, H.Rectangle(10, 10, 4, 4)), 7 / 9, 8, 28 / 3, -1, 0, 1e-12)
      -- Circle r = 1 by (12, 16) toward the face x = 8 of x [8, 12], y [-20, 20]: its right
      -- point reaches 8 after 7 in x: t = 7 / 12; the centre is then at (7, 16 * 7 / 12 =
      -- 28 / 3), the point (8, 28 / 3).
      isHit(weep(H.Circle(0, 0, 1), 12, 16, H.Rectangle(10, 0, 4, 40)), 7 / 12, 8, 28 / 3, -1, 0, 1e-12)
    end)
  end)

  describe('conventions', function()
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(30, 2, 10, 10) -- gap 20 along x (see above)

    it('the normal points from b toward a, whichever side b is on', function()
      -- b to the left (x [-35, -25]): moving by (-40, 0), t = 20 / 40 = 0.5, normal (1, 0).
      isHit(weep(a, -40, 0, H.Rectangle(-30, 2, 10, 10)), 0.5, -25, 1, 1, 0)
      -- b above (y [-35, -25] with y down): by (0, -40), normal (0, 1); shared x [-5, 5]
      -- with [-3, 7] = [-3, 5], middle 1: point (1, -25).
      isHit(weep(a, 0, -40, H.Rectangle(2, -30, 10, 10)), 0.5, 1, -25, 0, 1)
    end)

    it('a move too short, or away, or of zero length, is no hit; exactly long enough is t = 1', function()
      assert.is_false(weep(a, 19.5, 0, b)) -- the gap is 20
      assert.is_false(weep(a, -40, 0, b)) -- away
      assert.is_false(weep(a, 0, 40, b)) -- across, never reaching x = 25
      assert.is_false(weep(a, 0, 0, b)) -- no move
      assert.is_false(weep(H.Circle(0, 0, 2), 0, 15.9, H.Rectangle(0, 20, 10, 4))) -- needs 16
      -- a move of exactly the gap ends touching: the first touch is at t = 20 / 20 = 1
      isHit(weep(a, 20, 0, b), 1, 25, 1, -1, 0)
    end)

    it('touching at the start: moving apart or along the face is no hit; moving in is t = 0', function()
      -- a spans x [-5, 5], c x [5, 15]: they share the line x = 5 (touching is not
      -- overlapping).
      local c = H.Rectangle(10, 0, 10, 10)
      assert.is_false(S.triking(a, c))
      assert.is_false(weep(a, -5, 0, c)) -- apart
      assert.is_false(weep(a, -5, 3, c)) -- apart, slanted
      assert.is_false(weep(a, 0, 5, c)) -- along the touching face
      assert.is_false(weep(a, 0, -100, c))
      assert.is_false(weep(a, 0, 0, c))
      -- in: t = 0, not overlapping, normal (-1, 0), point in the middle of the shared face
      -- (x = 5, y in [-5, 5]): (5, 0)
      isHit(weep(a, 5, 0, c), 0, 5, 0, -1, 0)
      isHit(weep(a, 5, 3, c), 0, 5, 0, -1, 0)
      -- a circle r = 5 at the origin touches c at (5, 0)
      local o = H.Circle(0, 0, 5)
      assert.is_false(weep(o, 0, 3, c))
      assert.is_false(weep(o, -1, 0, c))
      isHit(weep(o, 1, 0, c), 0, 5, 0, -1, 0)
    end)

    -- A circle r = 2 at (10, 8) rests on the line y = 10 (its lowest point is (10, 10):
    -- 8 + 2); sliding by (40, 0) along the touching face must be no hit, as for the boxes and
    -- the circle above. The normal at the start comes from the closest point on the edge,
    -- x = 10.000000000000014 by round-off (normal (-7.1e-15, -1)): without the tolerance of
    -- kernels.APPROACH the move read as going in (t = 0).
    it('a circle resting on a long floor and sliding along it is no hit', function()
      local c = H.Circle(10, 8, 2)
      local e, slab = H.Edge(-100, 10, 100, 10), H.Rectangle(0, 15, 200, 10) -- both top at y = 10
      assert.is_false(S.triking(c, e))
      assert.is_false(S.triking(c, slab))
      isMiss(weep(c, 40, 0, e), 'circle (10, 8) r 2 by (40, 0) along Edge(-100, 10, 100, 10)')
      isMiss(weep(c, 40, 0, slab), 'circle (10, 8) r 2 by (40, 0) along Rectangle(0, 15, 200, 10)')
      isMiss(weep(c, 1, 0, e), 'circle (10, 8) r 2 by (1, 0) along Edge(-100, 10, 100, 10)')
    end)

    it('overlapping at the start: t = 0, overlapping = true, the normal opposite S.triking\'s', function()
      -- a spans x [-5, 5], y [-5, 5]; o spans x [3, 13], y [-4, 6]: they overlap by 2 along
      -- x (9 along y), so the MTV from a toward o is (1, 0) with depth 2 and the hit's normal
      -- is (-1, 0). The point is midway between a's deepest x (5) and o's (3): x = 4.
      local o = H.Rectangle(8, 1, 10, 10)
      local m = S.triking(a, o)
      near(m.nx, 1, TOL)
      near(m.ny, 0, TOL)
      near(m.depth, 2, TOL)
      for _, d in ipairs({ { 0, 0 }, { 10, 0 }, { -10, 0 }, { 0, 7 } }) do
        local h = weep(a, d[1], d[2], o)
        isHit(h, 0, 4, nil, -m.nx, -m.ny, TOL, true)
      end
      -- a circle inside a box: overlapping too
      local h = weep(H.Circle(0, 0, 1), 100, 0, a)
      assert.equals(0, h.t)
      assert.is_true(h.overlapping)
    end)

    it('fills `out` when given and returns it; makes a new table otherwise', function()
      local out = { t = 42, extra = 'kept' }
      local h = weep(a, 40, 0, b, nil, out)
      assert.equals(out, h)
      isHit(h, 0.5, 25, 1, -1, 0)
      assert.equals('kept', out.extra)
      -- angle 0 is a translation
      isHit(weep(a, 40, 0, b, 0, out), 0.5, 25, 1, -1, 0)
      assert.is_false(weep(a, -40, 0, b, nil, out))
      local h1, h2 = weep(a, 40, 0, b), weep(a, 40, 0, b)
      assert.are_not.equal(h1, h2)
    end)
  end)

  describe('tunnelling', function()
    -- A circle r = 2 starting at (90, 0), moving right by `speed` in one step. None of the
    -- moves below would find the wall by testing the end position alone, except the 10 px
    -- ones.
    for _, speed in ipairs({ 10, 50, 1000, 10000 }) do
      it(('a circle at %d px per move hits thick and thin walls and an edge'):format(speed), function()
        local c = H.Circle(90, 0, 2)
        -- 4 px wall x [98, 102]: the centre must reach 96, 6 away: t = 6 / speed
        isHit(weep(c, speed, 0, H.Rectangle(100, 0, 4, 200)), 6 / speed, 98, 0, -1, 0)
        -- 1 px wall x [99.5, 100.5]: the centre must reach 97.5: t = 7.5 / speed
        isHit(weep(c, speed, 0, H.Rectangle(100, 0, 1, 200)), 7.5 / speed, 99.5, 0, -1, 0)
        -- the edge x = 100: the centre must reach 98: t = 8 / speed
        isHit(weep(c, speed, 0, H.Edge(100, -100, 100, 100)), 8 / speed, 100, 0, -1, 0)
        -- and the same from the far side, moving left from (110, 0): the centre must reach
        -- 104 (4 px wall), 102.5 (1 px wall), 102 (edge): t = 6, 7.5, 8 over speed, normal (1, 0)
        local d = H.Circle(110, 0, 2)
        isHit(weep(d, -speed, 0, H.Rectangle(100, 0, 4, 200)), 6 / speed, 102, 0, 1, 0)
        isHit(weep(d, -speed, 0, H.Rectangle(100, 0, 1, 200)), 7.5 / speed, 100.5, 0, 1, 0)
        isHit(weep(d, -speed, 0, H.Edge(100, -100, 100, 100)), 8 / speed, 100, 0, 1, 0)
      end)
    end

    it('a point crossing an edge or a chain segment never meets it, whatever the last bits of its ends', function()
      -- (docs/moving.md: a point and an edge have no area between them to overlap, so a point
      -- swept across an edge is no hit, as S.triking never finds them colliding. Found by the
      -- world model: a point moving nearly head on into the middle of a chain segment far from
      -- the origin met it or passed through it as the segment's ends moved by 1e-12: a segment
      -- has no width, so the point enters it through one face at the time it leaves through
      -- the other, the same time but for rounding, which decided)
      local ax, ay, bx, by = -13665.859780229383, -392.32776717262249, -13689.702345416235, -378.10880933832107
      local px, py, dx, dy = -13607.725810206875, -324.20109083841442, -66.936942164293214, -72.970732121169249
      for k = -40, 40 do
        local e = k * 2.5e-11 * (1 + math.abs(k)) -- (0 and offsets from 2.5e-11 to 8e-8)
        for _, b in ipairs({ H.Edge(ax, ay + e, bx, by + e), T.Chain({ ax, ay + e, bx, by + e }),
          T.Chain({ ax + 9, ay - 8 + e, ax, ay + e, bx, by + e, bx - 20, by - 57 + e }) }) do
          isMiss(weep(H.Point(px, py), dx, dy, b), 'offset ' .. e)
        end
        -- and the edge moving onto the point (the edge's own faces, the same way round)
        isMiss(weep(H.Edge(ax, ay + e, bx, by + e), -dx, -dy, H.Point(px, py)), 'the edge moving, offset ' .. e)
      end
      -- Edge (0, 0)-(10, 0): a point straight down through its middle, through its end, an
      -- edge parallel to it moving onto it: no area between them, no hit
      isMiss(weep(H.Point(5, 5), 0, -10, H.Edge(0, 0, 10, 0)), 'through the middle')
      isMiss(weep(H.Point(12, 5), -4, -10, H.Edge(0, 0, 10, 0)), 'through the end')
      isMiss(weep(H.Edge(2, 5, 8, 5), 0, -10, H.Edge(0, 0, 10, 0)), 'a parallel edge')
    end)

    it('what has area between it and an edge meets it, however thin', function()
      -- Edge (0, 0)-(10, 0). A box 1e-7 tall, x [4, 6], y [5 - 5e-8, 5 + 5e-8], down by 10: its
      -- bottom reaches y = 0 at t = (5 - 5e-8) / 10; a point's move, fattened that little, hits.
      isHit(weep(H.Rectangle(5, 5, 2, 1e-7), 0, -10, H.Edge(0, 0, 10, 0)), 0.5 - 5e-9, nil, nil, 0, 1, 1e-12)
      -- An edge crossing it at a slant: (3, 4)-(7, 6) down by 10, its low end reaches y = 0 at
      -- t = 0.4, at x = 3 (a vertex of the moving edge on the still one's face)
      isHit(weep(H.Edge(3, 4, 7, 6), 0, -10, H.Edge(0, 0, 10, 0)), 0.4, 3, 0, 0, 1, 1e-12)
      -- A point touching it and moving away, or crossing its line past an end: no hit either
      isMiss(weep(H.Point(5, 0), 0, 5, H.Edge(0, 0, 10, 0)), 'up from the edge')
      isMiss(weep(H.Point(10.5, 5), 0, -10, H.Edge(0, 0, 10, 0)), 'past the end')
      -- A box's corner passed by, touched at one instant from outside: no hit. The box x [0, 10],
      -- y [-10, 0]; from (12, -2) by (-4, 4) to (8, 2): through (10, 0), its corner, outside it
      -- before (x > 10) and after (y > 0). Through the corner and into the box: a hit at 0.5.
      isMiss(weep(H.Point(12, -2), -4, 4, H.Rectangle(5, -5, 10, 10)), 'past a corner')
      local into = weep(H.Point(12, 2), -4, -4, H.Rectangle(5, -5, 10, 10))
      assert(into, 'through the corner into the box: a hit')
      near(into.t, 0.5, 1e-12, 't')
    end)

    it('a fast box hits a thin wall it would jump over', function()
      -- Box x [-5, 5] by (10000, 10000 / 3) against the wall x [99.5, 100.5], y [-100, 100]:
      -- x = 5 reaches 99.5 at t = 94.5 / 10000 = 0.00945, when y spans
      -- [-5, 5] + 0.00945 * 10000 / 3 = [26.5, 36.5]: middle 31.5.
      isHit(weep(H.Rectangle(0, 0, 10, 10), 10000, 10000 / 3, H.Rectangle(100, 0, 1, 200)), 0.00945, 99.5, 31.5,
        -1, 0, 1e-12)
    end)
  end)

  describe('chains', function()
    -- A floor given from left to right on a LÖVE screen: its free side is above (smaller y);
    -- the face normal (ey, -ex) / len = (0, -1).
    local floor = T.Chain(0, 10, 100, 10)

    it('a body above a floor chain falls onto it; the same body below moving up passes', function()
      -- box x [45, 55], y [-5, 5]; by (0, 10) its bottom reaches y = 10 after 5: t = 0.5,
      -- normal (0, -1), point the middle of [45, 55]: (50, 10)
      isHit(weep(H.Rectangle(50, 0, 10, 10), 0, 10, floor), 0.5, 50, 10, 0, -1)
      -- a circle r = 2 at (30, 0): bottom at 2, gap 8 of a move 16: t = 0.5, point (30, 10)
      isHit(weep(H.Circle(30, 0, 2), 0, 16, floor), 0.5, 30, 10, 0, -1)
      -- below (centroid y = 20 behind the segment) moving up through it: no hit
      assert.is_false(weep(H.Rectangle(50, 20, 10, 10), 0, -20, floor))
      assert.is_false(weep(H.Circle(30, 20, 2), 0, -20, floor))
      -- the floor moving (as body a) up into a box above it: the same meeting, normal from
      -- the box toward the chain (0, 1); box x [45, 55], y [-5, 5]: the floor meets y = 5
      -- after 5 of 10: t = 0.5, point (50, 5)
      isHit(weep(floor, 0, -10, H.Rectangle(50, 0, 10, 10)), 0.5, 50, 5, 0, 1)
      -- and up into a box below it: the box's centroid is behind, no hit
      assert.is_false(weep(floor, 0, 30, H.Rectangle(50, 20, 10, 10)))
    end)

    it('a box sliding along a row of chain segments, on them or a gap above, meets no seam', function()
      local row = T.Chain(0, 10, 20, 10, 40, 10, 60, 10) -- seams at x = 20 and x = 40
      local onIt = H.Rectangle(10, 5, 10, 10) -- y [0, 10]: resting on the row
      assert.is_false(S.triking(onIt, row))
      assert.is_false(weep(onIt, 40, 0, row))
      assert.is_false(weep(onIt, 45, 0, row))
      local above = H.Rectangle(10, 4, 10, 10) -- y [-1, 9]: a gap of 1
      assert.is_false(weep(above, 40, 0, row))
      assert.is_false(weep(above, 45, 0, row))
      -- circles, resting (bottom at 10) and a gap above (bottom at 9)
      assert.is_false(weep(H.Circle(5, 6, 4), 50, 0, row))
      assert.is_false(weep(H.Circle(5, 5, 4), 50, 0, row))
      -- moving back (right to left) over the seams
      assert.is_false(weep(H.Rectangle(50, 5, 10, 10), -45, 0, row))
      -- landing right on the seam x = 20: box x [15, 25], y [-5, 5] by (0, 10): the faces of
      -- both segments at t = 0.5, normal (0, -1) (not a corner's)
      local h = weep(H.Rectangle(20, 0, 10, 10), 0, 10, row)
      isHit(h, 0.5, nil, 10, 0, -1)
      assert(h.x >= 15 and h.x <= 25, 'the point lies under the box')
      -- landing on a seam while moving right: from x [5, 15], y [-5, 5] by (20, 10): y = 10
      -- at t = 0.5, where the box spans x [15, 25], across the seam: normal (0, -1)
      h = weep(H.Rectangle(10, 0, 10, 10), 20, 10, row)
      isHit(h, 0.5, nil, 10, 0, -1)
      assert(h.x >= 15 and h.x <= 25, 'the point lies under the box')
    end)

    -- The same slides with rounded bodies (the tolerance of kernels.APPROACH). The rounded
    -- box Rectangle(10, 5, 10, 10, 0, 2) spans y [0, 10] (core y [2, 8] grown by 2) and
    -- rests on the row; the circle r = 2 at (10, 8) rests on a one-segment
    -- floor (lowest point y = 10). Sliding by (40, 0) must be no hit; S.weep reports t = 0
    -- with a normal of (~-1e-15, -1) without it: see the circle case under 'conventions'.
    it('rounded bodies resting on a chain floor slide along it without a hit', function()
      local row = T.Chain(0, 10, 20, 10, 40, 10, 60, 10)
      local rr = H.Rectangle(10, 5, 10, 10, 0, 2)
      assert.is_false(S.triking(rr, row))
      isMiss(weep(rr, 40, 0, row), 'Rectangle(10, 5, 10, 10, 0, 2) by (40, 0) along the row')
      local c = H.Circle(10, 8, 2)
      local floor2 = T.Chain(-100, 10, 100, 10)
      assert.is_false(S.triking(c, floor2))
      isMiss(weep(c, 40, 0, floor2), 'circle (10, 8) r 2 by (40, 0) along Chain(-100, 10, 100, 10)')
    end)

    it('a box sliding over touching tiles (a collider of rectangles) meets no seam', function()
      -- tiles x [0, 20], [20, 40], [40, 60], all y [10, 20]
      local tiles = T.Collider(H.Rectangle(10, 15, 20, 10), H.Rectangle(30, 15, 20, 10), H.Rectangle(50, 15, 20, 10))
      assert.is_false(weep(H.Rectangle(10, 5, 10, 10), 40, 0, tiles)) -- resting on them
      assert.is_false(weep(H.Rectangle(10, 4, 10, 10), 40, 0, tiles)) -- a gap of 1 above
      -- landing on the seam x = 20 from x [5, 15] by (20, 10): t = 0.5, the face's normal
      -- (0, -1), not a corner's
      isHit(weep(H.Rectangle(10, 0, 10, 10), 20, 10, tiles), 0.5, nil, 10, 0, -1)
    end)
  end)

  describe('compounds', function()
    -- two 4 x 4 boxes: x [-2, 2] and x [8, 12], both y [-2, 2]
    local pair = T.Collider(H.Rectangle(0, 0, 4, 4), H.Rectangle(10, 0, 4, 4))

    it('the earliest member decides', function()
      -- toward the wall x [28, 32]: the right member is 16 away, the left one 26 (beyond the
      -- move of 20): t = 16 / 20 = 0.8, normal (-1, 0), point (28, 0)
      isHit(weep(pair, 20, 0, H.Rectangle(30, 0, 4, 40)), 0.8, 28, 0, -1, 0)
      -- toward the wall x [-22, -18]: the left member is 16 away: t = 0.8, point (-18, 0)
      isHit(weep(pair, -20, 0, H.Rectangle(-20, 0, 4, 40)), 0.8, -18, 0, 1, 0)
      -- the compound still, a box x [-22, -18], y [-2, 2] moving right by (40, 0): the left
      -- member is 16 away: t = 0.4, normal (from the pair toward the box) (-1, 0), point (-2, 0)
      isHit(weep(H.Rectangle(-20, 0, 4, 4), 40, 0, pair), 0.4, -2, 0, -1, 0)
      -- a still compound whose nearer member is the small one: a wall x [28, 32] and a
      -- block x [24, 26], y [-1, 1]; a box x [-2, 2] by (40, 0) meets the block after 22:
      -- t = 22 / 40 = 0.55, point (24, 0) (the middle of y [-2, 2] n [-1, 1])
      local wallAndBlock = T.Collider(H.Rectangle(30, 0, 4, 40), H.Rectangle(25, 0, 2, 2))
      isHit(weep(H.Rectangle(0, 0, 4, 4), 40, 0, wallAndBlock), 0.55, 24, 0, -1, 0)
      -- two compounds: the pair by (20, 0) against wallAndBlock: the right member (x
      -- [8, 12]) meets the block (x = 24) after 12: t = 12 / 20 = 0.6, point (24, 0)
      isHit(weep(pair, 20, 0, wallAndBlock), 0.6, 24, 0, -1, 0)
    end)

    it('members of one collider never hit each other', function()
      -- bare, the left member by (10, 0) would meet the right one (gap 6): t = 0.6
      isHit(weep(H.Rectangle(0, 0, 4, 4), 10, 0, H.Rectangle(10, 0, 4, 4)), 0.6, 8, 0, -1, 0)
      local m1, m2 = (pair:unpack()), select(2, pair:unpack())
      assert.is_false(weep(m1, 10, 0, m2))
      assert.is_false(weep(m2, -10, 0, m1))
      assert.is_false(weep(pair, 10, 0, m1))
      assert.is_false(weep(m2, 10, 0, pair))
      assert.is_false(weep(pair, 10, 0, pair))
      -- members of a nested collider too
      local inner = T.Collider(H.Rectangle(20, 0, 4, 4))
      local outer = T.Collider(H.Rectangle(0, 0, 4, 4), inner)
      assert.is_false(weep((outer:unpack()), 20, 0, (inner:unpack())))
    end)

    it('an empty collider hits nothing', function()
      local empty = T.Collider()
      local box = H.Rectangle(0, 0, 4, 4)
      assert.is_false(weep(empty, 10, 0, box))
      assert.is_false(weep(box, 10, 0, empty))
      assert.is_false(weep(empty, 0, 0, box))
      assert.is_false(weep(empty, 10, 0, T.Collider()))
      assert.is_false(weep(box, 10, 0, empty, 1))
    end)
  end)

  describe('rotation', function()
    -- Distance tolerance of a rotating sweep (strike/motion/sweep.lua): ROTATION_TOL times
    -- the bodies' size, the largest (width + height) of b's leaves plus twice a's reach rho.
    local ROTATION_TOL = sweepModule.ROTATION_TOL

    it('a long thin rectangle turning about its centre hits a box beside its tip', function()
      -- a spans x [-10, 10], y [-1, 1]; b spans x [8, 12], y [4, 8]. Turning by pi / 2 (x
      -- toward y: (x, y) -> (x c - y s, x s + y c)), the tip corner (10, 1) leads: over a's
      -- face y' = 1 the largest world y is at that corner, so the first touch is the corner
      -- meeting b's face y = 4 at the angle theta with 10 sin theta + cos theta = 4, i.e.
      -- sqrt(101) sin(theta + atan(1 / 10)) = 4:
      --   theta = asin(4 / sqrt(101)) - atan(0.1) ~ 0.30970 rad
      -- The corner is then at x = sqrt(101 - 16) = sqrt(85) ~ 9.22, within b's [8, 12]; b's
      -- nearest corner (8, 4) is still at a's local y' = 4 cos - 8 sin ~ 1.37 > 1 (untouched).
      -- t = theta / (pi / 2); normal (0, -1); point (sqrt(85), 4).
      local a, b = H.Rectangle(0, 0, 20, 2), H.Rectangle(10, 6, 4, 4)
      local theta = asin(4 / sqrt(101)) - atan(0.1)
      local tTrue = theta / (pi / 2)
      -- The tolerance in t: the sweep stops within ROTATION_TOL * (size + 2 rho) of touching
      -- (size = 4 + 4 = 8, rho = sqrt(101) the tip's reach); near the touch the corner closes
      -- on y = 4 at (pi / 2) * sqrt(85) per unit of t (its speed times the cosine of its
      -- heading), so t is early by at most about that distance over that speed (doubled).
      local tTol = 2 * ROTATION_TOL * (8 + 2 * sqrt(101)) / ((pi / 2) * sqrt(85))
      local h = weep(a, 0, 0, b, pi / 2)
      assert(h, 'expected a hit')
      assert.is_false(h.overlapping)
      assert(h.t <= tTrue + 1e-15, ('t = %.17g is after the true first touch %.17g'):format(h.t, tTrue))
      assert(h.t >= tTrue - tTol, ('t = %.17g is more than %g before %.17g'):format(h.t, tTol, tTrue))
      near(h.nx, 0, 1e-6, 'nx')
      near(h.ny, -1, 1e-6, 'ny')
      near(h.x, sqrt(85), 1e-6, 'x')
      near(h.y, 4, 1e-6, 'y')
    end)

    it('turning too little, or the other way, is no hit', function()
      local a, b = H.Rectangle(0, 0, 20, 2), H.Rectangle(10, 6, 4, 4)
      assert.is_false(weep(a, 0, 0, b, 0.25)) -- the touch is at 0.3097 rad
      -- turning by -pi / 2 the right half swings toward -y, away from b
      assert.is_false(weep(a, 0, 0, b, -pi / 2))
    end)

    -- Touching at the start and moving in is a hit at t = 0 with or without a turn, as the
    -- translation gives. Boxes a (x [-5, 5]) and b (x [5, 15]) share the line x = 5; a
    -- moving by (5, 0) while turning by 0.1 ends 5 deep inside b. Likewise the thin
    -- rectangle (y [-1, 1]) turning by +0.5 under a box x [3, 7], y [1, 5] resting on its
    -- face y = 1: the face's right part (x > 0) swings toward +y into the box at once, t = 0,
    -- normal (0, -1). (For two sharp bodies that touch, the cores' closest points coincide:
    -- the normal is the axis that separates them least, kernels.coreOverlap.)
    it('turning bodies that touch at the start and move in hit at t = 0', function()
      local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10)
      assert.is_false(S.triking(a, b))
      isHit(weep(a, 5, 0, b), 0, 5, 0, -1, 0) -- (the translation: right)
      local h = weep(a, 5, 0, b, 0.1)
      assert(h, 'a box turning by 0.1 while moving 5 into a box it touches: expected t = 0, got false')
      isHit(h, 0, 5, nil, -1, 0, 1e-9)
      assert(h.y >= -5 and h.y <= 5, 'the point lies on the shared face')
      local thin, box = H.Rectangle(0, 0, 20, 2), H.Rectangle(5, 3, 4, 4)
      h = weep(thin, 0, 0, box, 0.5)
      assert(h, 'a thin rectangle turning into a box resting on it: expected t = 0, got false')
      isHit(h, 0, nil, 1, 0, -1, 1e-9)
      assert(h.x >= 3 and h.x <= 7, 'the point lies on the shared face')
      -- (turning the other way, the face's right part leaves the box: no hit)
      assert.is_false(weep(thin, 0, 0, box, -0.5))
    end)

    it('a turning circle hits as a translating one, never later', function()
      -- Circle r = 2 by (32, 0) toward the wall x [18, 22]: t = 16 / 32 = 0.5 whatever its
      -- spin; normal (-1, 0), point (18, 0).
      local h = weep(H.Circle(0, 0, 2), 32, 0, H.Rectangle(20, 0, 4, 40), 1)
      assert(h.t <= 0.5 + 1e-15, ('t = %.17g is after 0.5'):format(h.t))
      -- ROTATION_TOL * (44 + 2 * 2) in distance, closing at 32 per unit of t (doubled)
      near(h.t, 0.5, 2 * ROTATION_TOL * 48 / 32, 't')
      near(h.nx, -1, 1e-6, 'nx')
      near(h.ny, 0, 1e-6, 'ny')
      near(h.x, 18, 1e-6, 'x')
      near(h.y, 0, 1e-6, 'y')
    end)
  end)

  describe('errors at the caller\'s line', function()
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(30, 0, 10, 10)
    local nan, inf = 0 / 0, math.huge
    local BODY = 'must be a strike collider or shape, got '
    local NUM = 'must be a finite number, got '
    local ANGLE = 'strike.weep: argument 5 (angle) must be a finite number or nil'
    local OUT = 'strike.weep: argument 6 (out) must be a plain table'

    it('bodies', function()
      raisesAt(function() S.weep(42, 1, 0, b) end, 'strike.weep: argument 1 ' .. BODY .. '42')
      raisesAt(function() S.weep(nil, 1, 0, b) end, 'strike.weep: argument 1 ' .. BODY .. 'nil')
      raisesAt(function() S.weep({}, 1, 0, b) end, 'strike.weep: argument 1 ' .. BODY .. 'table')
      raisesAt(function() S.weep(S.MTV(), 1, 0, b) end, 'strike.weep: argument 1 ' .. BODY .. 'table')
      raisesAt(function() S.weep(a, 1, 0, 'b') end, 'strike.weep: argument 4 ' .. BODY .. 'string')
      raisesAt(function() S.weep(a, 1, 0) end, 'strike.weep: argument 4 ' .. BODY .. 'nil')
      raisesAt(function() S.weep(a, 1, 0, {}) end, 'strike.weep: argument 4 ' .. BODY .. 'table')
    end)

    it('the move', function()
      raisesAt(function() S.weep(a, nan, 0, b) end, 'strike.weep: argument 2 (dx) ' .. NUM .. 'nan')
      raisesAt(function() S.weep(a, inf, 0, b) end, 'strike.weep: argument 2 (dx) ' .. NUM .. 'inf')
      raisesAt(function() S.weep(a, '1', 0, b) end, 'strike.weep: argument 2 (dx) ' .. NUM .. 'string')
      raisesAt(function() S.weep(a, nil, 0, b) end, 'strike.weep: argument 2 (dx) ' .. NUM .. 'nil')
      raisesAt(function() S.weep(a, 1, nan, b) end, 'strike.weep: argument 3 (dy) ' .. NUM .. 'nan')
      raisesAt(function() S.weep(a, 1, -inf, b) end, 'strike.weep: argument 3 (dy) ' .. NUM .. '-inf')
      raisesAt(function() S.weep(a, 1, {}, b) end, 'strike.weep: argument 3 (dy) ' .. NUM .. 'table')
      raisesAt(function() S.weep(a, 1, nil, b) end, 'strike.weep: argument 3 (dy) ' .. NUM .. 'nil')
    end)

    it('the angle', function()
      raisesAt(function() S.weep(a, 1, 0, b, 'x') end, ANGLE)
      raisesAt(function() S.weep(a, 1, 0, b, nan) end, ANGLE .. ', got nan')
      raisesAt(function() S.weep(a, 1, 0, b, inf) end, ANGLE .. ', got inf')
      raisesAt(function() S.weep(a, 1, 0, b, true) end, ANGLE .. ', got true')
    end)

    it('out', function()
      raisesAt(function() S.weep(a, 1, 0, b, nil, 42) end, OUT)
      raisesAt(function() S.weep(a, 1, 0, b, nil, 'o') end, OUT)
      raisesAt(function() S.weep(a, 1, 0, b, 0, S.MTV()) end, OUT)
      raisesAt(function() S.weep(a, 1, 0, b, nil, S.MTV()) end, 'got an MTV')
      raisesAt(function() S.weep(a, 1, 0, b, nil, H.Point(0, 0)) end, OUT)
    end)

    it('S.eparation', function()
      raisesAt(function() S.eparation(1, b) end, 'strike.eparation: argument 1 ' .. BODY .. '1')
      raisesAt(function() S.eparation(nil, b) end, 'strike.eparation: argument 1 ' .. BODY .. 'nil')
      raisesAt(function() S.eparation({}, b) end, 'strike.eparation: argument 1 ' .. BODY .. 'table')
      raisesAt(function() S.eparation(a) end, 'strike.eparation: argument 2 ' .. BODY .. 'nil')
      raisesAt(function() S.eparation(a, 'b') end, 'strike.eparation: argument 2 ' .. BODY .. 'string')
      raisesAt(function() S.eparation(a, S.MTV()) end, 'strike.eparation: argument 2 ' .. BODY .. 'table')
    end)
  end)

  describe('allocation', function()
    setup(alloc.jitOff) -- measured interpreted on LuaJIT: see spec/helpers/alloc.lua
    teardown(alloc.jitOn)

    it('with `out`, sweeps that translate allocate nothing', function()
      local out = {}
      local box, wall = H.Rectangle(0, 0, 10, 10), H.Rectangle(30, 2, 10, 10)
      local circle, rounded = H.Circle(0, 0, 2), H.Rectangle(0, 0, 10, 10, 0, 2)
      local pair = T.Collider(H.Rectangle(0, 0, 4, 4), H.Rectangle(10, 0, 4, 4))
      local floor = T.Chain(0, 10, 20, 10, 40, 10)
      local overlapping = H.Rectangle(8, 1, 10, 10)
      local weepFn = S.weep
      local function sweeps()
        weepFn(box, 40, 0, wall, nil, out) -- hit
        weepFn(box, -40, 0, wall, nil, out) -- miss
        weepFn(circle, 40, 3, wall, nil, out) -- rounded against sharp
        weepFn(rounded, 30, 0, wall, 0, out)
        weepFn(pair, 30, 0, wall, nil, out) -- compound
        weepFn(box, 0, 20, floor, nil, out) -- chain
        weepFn(box, 5, 0, overlapping, nil, out) -- overlapping
      end
      assert.equals(0.5, weepFn(box, 40, 0, wall, nil, out).t) -- (gap 20 of 40)
      local kb = alloc.kbPer(sweeps, 1000)
      assert(kb < alloc.ONE_TIME_KB, ('7,000 sweeps allocated %.3f KB'):format(kb))
    end)

    it('with `out`, a turning sweep allocates nothing either', function()
      local out, thin, beside = {}, H.Rectangle(0, 0, 20, 2), H.Rectangle(10, 6, 4, 4) -- (see 'rotation')
      local weepFn = S.weep
      local kb = alloc.kbPer(function() weepFn(thin, 0, 0, beside, pi / 2, out) end, 1000, 2000)
      assert(kb < alloc.ONE_TIME_KB, ('1,000 turning sweeps allocated %.3f KB'):format(kb))
    end)

    it('S.eparation allocates nothing', function()
      local box, wall = H.Rectangle(0, 0, 10, 10), H.Rectangle(30, 2, 10, 10)
      local circle, overlapping = H.Circle(0, 0, 2), H.Rectangle(8, 1, 10, 10)
      local sep = S.eparation
      local kb = alloc.kbPer(function()
        sep(box, wall)
        sep(circle, wall)
        sep(box, overlapping)
      end, 1000)
      assert(kb < alloc.ONE_TIME_KB, ('3,000 separations allocated %.3f KB'):format(kb))
    end)
  end)
end)

describe('S.eparation', function()
  it('two boxes apart: the distance and the closest points', function()
    -- a spans [-5, 5] both ways; b spans x [15, 25], y [7, 17]: b is past a's corner (5, 5)
    -- on both axes, so the closest points are the corners (5, 5) and (15, 7):
    -- d = sqrt(10^2 + 2^2) = sqrt(104)
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(20, 12, 10, 10)
    local d, ax, ay, bx, by = S.eparation(a, b)
    near(d, sqrt(104), TOL)
    near(ax, 5, TOL) near(ay, 5, TOL) near(bx, 15, TOL) near(by, 7, TOL)
    -- the other way round: the points swap
    d, ax, ay, bx, by = S.eparation(b, a)
    near(d, sqrt(104), TOL)
    near(ax, 15, TOL) near(ay, 7, TOL) near(bx, 5, TOL) near(by, 5, TOL)
    -- face to face (x [15, 25], y [-2, 8]): d = 15 - 5 = 10, the points on x = 5 and x = 15
    -- at one y of the shared [-2, 5]
    d, ax, ay, bx, by = S.eparation(a, H.Rectangle(20, 3, 10, 10))
    near(d, 10, TOL)
    near(ax, 5, TOL) near(bx, 15, TOL) near(ay, by, TOL)
    assert(ay >= -2 and ay <= 5, 'the closest points lie on the shared span')
  end)

  it('circle and circle', function()
    -- centres (0, 0) and (6, 8), 10 apart; radii 2 and 3: d = 5. Along (0.6, 0.8):
    -- (0, 0) + 2 (0.6, 0.8) = (1.2, 1.6) and (6, 8) - 3 (0.6, 0.8) = (4.2, 5.6)
    local d, ax, ay, bx, by = S.eparation(H.Circle(0, 0, 2), H.Circle(6, 8, 3))
    near(d, 5, TOL)
    near(ax, 1.2, TOL) near(ay, 1.6, TOL) near(bx, 4.2, TOL) near(by, 5.6, TOL)
  end)

  it('a box and a circle near its corner: the distance to the corner', function()
    -- box corner (5, 5); circle r = 2 at (8, 9), past the corner on both axes: distance to
    -- the corner sqrt(3^2 + 4^2) = 5, so d = 5 - 2 = 3; the circle's point is
    -- (8, 9) - 2 (0.6, 0.8) = (6.8, 7.4)
    local d, ax, ay, bx, by = S.eparation(H.Rectangle(0, 0, 10, 10), H.Circle(8, 9, 2))
    near(d, 3, TOL)
    near(ax, 5, TOL) near(ay, 5, TOL) near(bx, 6.8, TOL) near(by, 7.4, TOL)
  end)

  it('overlapping boxes: minus the depth, and the deepest points along the MTV', function()
    -- a spans x [-5, 5]; b spans x [3, 13], y [-4, 6]: depth 2 along x (9 along y). The MTV
    -- from a toward b is (1, 0): a's deepest x is 5, b's is 3.
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(8, 1, 10, 10)
    local d, ax, ay, bx, by = S.eparation(a, b)
    near(d, -2, TOL)
    near(ax, 5, TOL) near(bx, 3, TOL)
    assert(ay >= -5 and ay <= 5 and by >= -4 and by <= 6, 'the points lie on the boxes')
    assert.equals(-S.triking(a, b).depth, d)
  end)

  it('capsule and edge', function()
    -- Capsule(0, 0, 4, 10): core (0, -3)-(0, 3), radius 2. The edge on x + y = 20 from
    -- (0, 20) to (20, 0): the core end (0, 3) is nearest, at (20 - 3) / sqrt(2) = 17 / sqrt(2);
    -- d = 17 / sqrt(2) - 2. Its foot on the edge is (0, 3) + (17 / 2) (1, 1) = (8.5, 11.5);
    -- the capsule's point is (0, 3) + 2 (1, 1) / sqrt(2) = (sqrt(2), 3 + sqrt(2)).
    local d, ax, ay, bx, by = S.eparation(H.Capsule(0, 0, 4, 10), H.Edge(0, 20, 20, 0))
    near(d, 17 / sqrt(2) - 2, 1e-12)
    near(ax, sqrt(2), 1e-12) near(ay, 3 + sqrt(2), 1e-12) near(bx, 8.5, 1e-12) near(by, 11.5, 1e-12)
    -- side by side with the vertical edge x = 10 (y [-20, 20]): d = 10 - 2 = 8, the points
    -- on x = 2 and x = 10 at one y of the core's [-3, 3]
    d, ax, ay, bx, by = S.eparation(H.Capsule(0, 0, 4, 10), H.Edge(10, -20, 10, 20))
    near(d, 8, TOL)
    near(ax, 2, TOL) near(bx, 10, TOL) near(ay, by, TOL)
    assert(ay >= -3 and ay <= 3, 'the closest points face the core')
  end)

  it('touching bodies are 0 apart; compounds take the nearest member', function()
    local d = S.eparation(H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10)) -- share x = 5
    near(d, 0, TOL)
    -- pair members x [-2, 2] and x [8, 12] (y [-2, 2]); circle r = 1 at (20, 0): the right
    -- member is nearest, 20 - 1 - 12 = 7 away, points (12, 0) and (19, 0)
    local pair = T.Collider(H.Rectangle(0, 0, 4, 4), H.Rectangle(10, 0, 4, 4))
    local ax, ay, bx, by
    d, ax, ay, bx, by = S.eparation(pair, H.Circle(20, 0, 1))
    near(d, 7, TOL)
    near(ax, 12, TOL) near(ay, 0, TOL) near(bx, 19, TOL) near(by, 0, TOL)
  end)
end)
