-- S.ite on compound MTVs (bodies with several members between them): every member pair that
-- overlaps before the second body moves by the MTV and touches after it gives its points
-- where the two touch after that move (on both surfaces), each with the pair's own normal
-- (the face it touches along) and the pair's own depth along that normal before the move.
-- Every expected value below is worked out by hand in the comments, never by strike.
local S = require('strike')
local expect = require('spec.helpers.expect')
local near = expect.near
local H, T = S.hapes, S.trikers

local sqrt = math.sqrt

-- c must hold exactly the points of `want`, in any order: each { a, b, x, y, nx, ny, depth }
-- with a, b the member shapes the point names.
local function expectPoints(c, want, tol)
  tol = tol or 1e-9
  assert(c, 'no contacts')
  assert(c.count == #want, ('%d points, expected %d'):format(c.count, #want))
  assert(#c == c.count, '#contacts is not its count')
  local used = {}
  for _, w in ipairs(want) do
    local found
    for i = 1, c.count do
      local p = c[i]
      if not used[i] and p.colliderShape == w[1] and p.collidedShape == w[2] and math.abs(p.x - w[3]) <= tol
        and math.abs(p.y - w[4]) <= tol and math.abs(p.nx - w[5]) <= tol and math.abs(p.ny - w[6]) <= tol
        and math.abs(p.depth - w[7]) <= tol then
        found = i
        break
      end
    end
    if not found then
      local got = {}
      for i = 1, c.count do
        local p = c[i]
        got[i] = ('(%s, %s) n (%s, %s) depth %s'):format(p.x, p.y, tostring(p.nx), tostring(p.ny), p.depth)
      end
      error(('no point (%.17g, %.17g) n (%.17g, %.17g) depth %.17g; got %s'):format(w[3], w[4], w[5], w[6], w[7],
        table.concat(got, ', ')), 2)
    end
    used[found] = true
  end
end

-- The members of a collider, in order.
local function members(c)
  local list = {}
  for s in c:elems() do list[#list + 1] = s end
  return list
end

describe('S.ite on compound MTVs', function()
  it('a box pushed diagonally out of the inner corner of an L made of two rectangles', function()
    -- bars [0, 100] x [0, 20] and [0, 20] x [0, 100]; the box [17, 27]^2 is 3 into each.
    -- Leaving one bar leaves the box in the other: the push is (3, 3), and the box, moved to
    -- [20, 30]^2, lies on the first bar's top face y = 20 from x = 20 to 30 (normal (0, 1)
    -- from the bar toward the box) and against the second's face x = 20 from y = 20 to 30
    -- (normal (1, 0)). Each pair overlapped by 3 along its own normal before the push.
    local bar1, bar2 = H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100)
    local L = T.Collider(bar1, bar2)
    local box = H.Rectangle(22, 22, 10, 10)
    local m = S.triking(L, box)
    near(m.x, 3)
    near(m.y, 3)
    local c = S.ite(m)
    near(c.nx, 1 / sqrt(2))
    near(c.ny, 1 / sqrt(2))
    expectPoints(c, {
      { bar1, box, 20, 20, 0, 1, 3 }, { bar1, box, 30, 20, 0, 1, 3 },
      { bar2, box, 20, 20, 1, 0, 3 }, { bar2, box, 20, 30, 1, 0, 3 },
    })
    -- in member order: the first bar's points, then the second's
    assert.equals(bar1, c[1].colliderShape)
    assert.equals(bar1, c[2].colliderShape)
    assert.equals(bar2, c[3].colliderShape)
    assert.equals(bar2, c[4].colliderShape)
  end)

  it('the same L, the box first: the points lie on the box, which stays, with the normals turned', function()
    -- the L moves by (-3, -3): bars [-3, 97] x [-3, 17] and [-3, 17] x [-3, 97] touch the
    -- box [17, 27]^2 along its top face y = 17 (x from 17 to 27; normal (0, -1) from the box
    -- toward the bar) and its left face x = 17 (y from 17 to 27; normal (-1, 0))
    local bar1, bar2 = H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100)
    local box = H.Rectangle(22, 22, 10, 10)
    local m = S.triking(box, T.Collider(bar1, bar2))
    near(m.x, -3)
    near(m.y, -3)
    expectPoints(S.ite(m), {
      { box, bar1, 17, 17, 0, -1, 3 }, { box, bar1, 27, 17, 0, -1, 3 },
      { box, bar2, 17, 17, -1, 0, 3 }, { box, bar2, 17, 27, -1, 0, 3 },
    })
  end)

  it('the inner corner of S.trikers.Concave: the pieces\' own faces, never the seam', function()
    -- the L outline (0, 0) (100, 0) (100, 20) (20, 20) (20, 100) (0, 100): the same corner
    -- as above, cut into two pieces along a seam; the box leaves by (3, 3) and touches the
    -- outline's faces y = 20 and x = 20, whichever piece each belongs to. (This is the case
    -- that gave points 30 outside both bodies, 81 deep, before: a pair's points computed
    -- along the push's diagonal.)
    local L = T.Concave(0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100)
    local box = H.Rectangle(22, 22, 10, 10)
    local m = S.triking(L, box)
    near(m.x, 3)
    near(m.y, 3)
    local c = S.ite(m)
    local pieces = members(L)
    assert.equals(2, #pieces)
    -- which piece holds which face: the one containing (10, 50) holds x = 20, y > 20
    local up, across = pieces[1], pieces[2]
    if not up:containsPoint(10, 50) then up, across = across, up end
    expectPoints(c, {
      { across, box, 20, 20, 0, 1, 3 }, { across, box, 30, 20, 0, 1, 3 },
      { up, box, 20, 20, 1, 0, 3 }, { up, box, 20, 30, 1, 0, 3 },
    })
  end)

  it('each pair has its own depth: a box 2 into one bar and 4 into the other', function()
    -- the box [18, 28] x [16, 26]: 4 into the bar y < 20, 2 into the bar x < 20; the push
    -- (2, 4) (length sqrt 20) takes it to [20, 30]^2, as above; the first pair's depth
    -- along (0, 1) is 4, the second's along (1, 0) is 2, both under sqrt 20
    local bar1, bar2 = H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100)
    local box = H.Rectangle(23, 21, 10, 10)
    local m = S.triking(T.Collider(bar1, bar2), box)
    near(m.x, 2)
    near(m.y, 4)
    near(m.depth, sqrt(20))
    expectPoints(S.ite(m), {
      { bar1, box, 20, 20, 0, 1, 4 }, { bar1, box, 30, 20, 0, 1, 4 },
      { bar2, box, 20, 20, 1, 0, 2 }, { bar2, box, 20, 30, 1, 0, 2 },
    })
  end)

  it('a circle pushed out of the inner corner touches each bar once, along its face', function()
    -- the circle (22, 22) r 3 is 1 into each bar; its centre must reach x >= 23 and y >= 23:
    -- the push (1, 1); it then touches y = 20 at (23, 20) and x = 20 at (20, 23)
    local bar1, bar2 = H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100)
    local ball = H.Circle(22, 22, 3)
    local m = S.triking(T.Collider(bar1, bar2), ball)
    near(m.x, 1)
    near(m.y, 1)
    expectPoints(S.ite(m), { { bar1, ball, 23, 20, 0, 1, 1 }, { bar2, ball, 20, 23, 1, 0, 1 } })
  end)

  it('rounded members and a rounded box: the points on the flat parts of the surfaces', function()
    -- the bars rounded by 2 cover the same [0, 100] x [0, 20] and [0, 20] x [0, 100] (cores
    -- 2 inside), so the union's inner corner is the same sharp one; the box [17, 27]^2
    -- rounded by 1 (core [18, 26]^2) must bring its core to x, y >= 21: the push is (3, 3).
    -- Moved, its bottom's flat part (x from 21 to 29) lies on y = 20, its left's (y from 21
    -- to 29) on x = 20.
    local bar1, bar2 = H.Rectangle(50, 10, 100, 20, 0, 2), H.Rectangle(10, 50, 20, 100, 0, 2)
    local box = H.Rectangle(22, 22, 10, 10, 0, 1)
    local m = S.triking(T.Collider(bar1, bar2), box)
    near(m.x, 3)
    near(m.y, 3)
    expectPoints(S.ite(m), {
      { bar1, box, 21, 20, 0, 1, 3 }, { bar1, box, 29, 20, 0, 1, 3 },
      { bar2, box, 20, 21, 1, 0, 3 }, { bar2, box, 20, 29, 1, 0, 3 },
    })
  end)

  it('a circle lifted out of a gap between two boxes touches both corners (no face)', function()
    -- boxes [0, 10] x [0, 10] and [18, 28] x [0, 10]; the circle (14, 3) r 5 is 1 into each.
    -- Its centre must stay 5 from both: the nearest free place is where the circles of
    -- radius 5 about the corners (10, 0) and (18, 0) cross, (14, -3): the push (0, -6).
    -- There the circle touches each box at that corner; the normal from the corner toward
    -- the centre is (4, -3) / 5 (and (-4, -3) / 5); depth along it: (-3 / 5) (-6) = 3.6.
    local left, right = H.Rectangle(5, 5, 10, 10), H.Rectangle(23, 5, 10, 10)
    local ball = H.Circle(14, 3, 5)
    local m = S.triking(T.Collider(left, right), ball)
    near(m.x, 0)
    near(m.y, -6)
    expectPoints(S.ite(m), { { left, ball, 10, 0, 0.8, -0.6, 3.6 }, { right, ball, 18, 0, -0.8, -0.6, 3.6 } })
  end)

  it('two circles of a compound and a circle between them: the normals along the centre lines', function()
    -- circles (0, 0) and (8, 0) r 5, the circle (4, 2) r 2: its centre must stay 7 from both
    -- centres; the nearest such place is where those circles cross, (4, sqrt 33): the push
    -- (0, sqrt 33 - 2). Normals (4, sqrt 33) / 7 and (-4, sqrt 33) / 7; the points 5 along
    -- them from the centres; depth (sqrt 33 / 7)(sqrt 33 - 2) = (33 - 2 sqrt 33) / 7.
    local c1, c2 = H.Circle(0, 0, 5), H.Circle(8, 0, 5)
    local ball = H.Circle(4, 2, 2)
    local m = S.triking(T.Collider(c1, c2), ball)
    local r33 = sqrt(33)
    near(m.x, 0, 1e-9)
    near(m.y, r33 - 2, 1e-9)
    local depth = (33 - 2 * r33) / 7
    expectPoints(S.ite(m), {
      { c1, ball, 20 / 7, 5 * r33 / 7, 4 / 7, r33 / 7, depth },
      { c2, ball, 8 - 20 / 7, 5 * r33 / 7, -4 / 7, r33 / 7, depth },
    }, 1e-9)
  end)

  it('a corner on a corner: the face most aligned with the push, one point per pair', function()
    -- tiles [0, 10] x [0, 10] and [10, 20] x [0, 10]; a square turned 45 degrees, half-diagonal
    -- 5, its bottom corner at (10, 1), 1 into both: the push is (0, -1), and its corner then
    -- rests on both tiles' corners (10, 0). Along each tile's top face (normal (0, -1), depth
    -- 1) and along the square's face through that corner (normal (1, -1) / sqrt 2 or
    -- (-1, -1) / sqrt 2, depth 1 / sqrt 2) alike, a line separates the two: the face taken is
    -- the one most aligned with the push, the tile's.
    -- The scene is turned by a quarter turn at a time about (10, 0) (which face comes first
    -- in a pair's difference turns with it): (x, y) -> (-y, x) about that corner.
    for q = 0, 3 do
      local function turn(x, y)
        x, y = x - 10, y
        for _ = 1, q do x, y = -y, x end
        return x + 10, y
      end
      local lx, ly = turn(5, 5)
      local rx, ry = turn(15, 5)
      local dx, dy = turn(10, -4)
      local left, right = H.Rectangle(lx, ly, 10, 10), H.Rectangle(rx, ry, 10, 10)
      local diamond = H.Rectangle(dx, dy, 5 * sqrt(2), 5 * sqrt(2), math.pi / 4)
      local m = S.triking(T.Collider(left, right), diamond)
      local mx, my = turn(10, -1)
      near(m.x, mx - 10, 1e-12)
      near(m.y, my, 1e-12)
      local nx, ny = turn(10, -1)
      nx = nx - 10
      expectPoints(S.ite(m), { { left, diamond, 10, 0, nx, ny, 1 }, { right, diamond, 10, 0, nx, ny, 1 } }, 1e-12)
    end
  end)

  it('keeps the first body\'s face for a box on a turned floor of tiles, where round-off splits the faces', function()
    -- tiles and box turned the same way, far from the origin: the tiles' top faces and the
    -- box's bottom face are parallel up to round-off, and either passes through the push;
    -- the first body's (side 0 in every id) is kept, as S.AT keeps it for one pair
    local floor = math.floor
    local cases = 0
    for _, at in ipairs({ { 100000.3, 100000.6, 0.2 }, { 12345.67, 76543.21, 0.6 }, { 3e4, -2e4, -2.5 } }) do
      local ox, oy, a = at[1], at[2], at[3]
      local c, s = math.cos(a), math.sin(a)
      local tiles = {}
      for i = 0, 2 do tiles[#tiles + 1] = H.Rectangle(ox + 20 * i * c, oy + 20 * i * s, 20, 10, a) end
      local ground = T.Collider((table.unpack or unpack)(tiles)) -- luacheck: ignore 113 143
      for k = 1, 100 do
        -- the box centred u along the floor from the first tile's centre, sunk d (normal up:
        -- (s, -c), y down)
        local u, d = 5 + k * 0.3, 0.05 + (k % 7) * 0.05
        local box = H.Rectangle(ox + u * c + s * (10 - d), oy + u * s - c * (10 - d), 10, 10, a)
        for _, order in ipairs({ { ground, box }, { box, ground } }) do
          local m = S.triking(order[1], order[2])
          local cts = S.ite(m)
          assert(cts and cts.count >= 2, ('case %d: %s points'):format(k, cts and cts.count or 'no'))
          for i = 1, cts.count do
            cases = cases + 1
            assert(floor(cts[i].id / (4 * 65536 * 65536)) == 0,
              ('angle %g case %d: point %d names the second body\'s face'):format(a, k, i))
          end
        end
      end
    end
    assert(cases > 1000, 'too few points')
  end)

  it('a corner at the end of a face, which round-off puts past that end, still gives its point', function()
    -- (found by the property spec, seed 119) two Concave outlines: after the push, the corner
    -- (-47.753132380140663, 31.730887377857272) of the first rests on the second, and each
    -- of the 4 piece pairs that meet there gives that one point; for one of them the
    -- touching face of the second ends at the corner, and clipping cut the whole incident
    -- face off at that end
    local a = T.Concave({ -47.109671826361073, 32.793231540470302, -47.035837142521046, 33.333338040909354,
      -47.676954022846914, 33.358737270727346, -47.735144716143019, 32.993839616776306, -48.273432050174797,
      33.000123024150888, -48.363469557547795, 32.662561487872544, -48.089172096320702, 31.791378021082995,
      -47.942900505044953, 31.867534544307539, -47.753132380140663, 31.730887377857272, -47.618891767393144,
      32.068234186181506, -47.231883842985873, 32.283364173913327, -47.21532389949482, 32.56021938506391 })
    local b = T.Concave({ -47.718561052005789, 33.098465527355081, -47.975287776785436, 32.974257554144998,
      -48.708874091754119, 33.028004883041945, -48.490414961935912, 32.330537444503136, -48.16788994002831,
      32.162246288729925, -47.938853009241598, 31.384105379790359, -47.323499852154335, 32.093526408769186,
      -46.95613177028256, 31.874244639452858 })
    b:translate(0.27895380439913287, -0.3337876604817509)
    local c = S.ite(S.triking(a, b))
    assert.equals(4, c.count)
    for i = 1, c.count do
      near(c[i].x, -47.753132380140663, 1e-9)
      near(c[i].y, 31.730887377857272, 1e-9)
      for j = 1, i - 1 do -- (4 different pairs)
        assert(c[j].colliderShape ~= c[i].colliderShape or c[j].collidedShape ~= c[i].collidedShape)
      end
    end
  end)

  it('a push smaller than the touching tolerance, far from the origin, still gives its points', function()
    -- tiles [5000, 5032] and [5032, 5064] (x) by [5000, 5032] (y); the box [5012, 5052] x
    -- [4960, 5000 + d] sunk d = 2^-17 (about 7.6e-6, below the round-off allowed in touching
    -- at 5,000 from the origin): the push (0, -d); on each tile 2 points on y = 5000, normal
    -- (0, -1), depth d
    local d = 2 ^ -17
    local t1, t2 = H.Rectangle(5016, 5016, 32, 32), H.Rectangle(5048, 5016, 32, 32)
    local box = H.Rectangle(5032, 4980 + d, 40, 40)
    local m = S.triking(T.Collider(t1, t2), box)
    near(m.x, 0, 0)
    near(m.y, -d, 1e-15)
    expectPoints(S.ite(m), {
      { t1, box, 5012, 5000, 0, -1, d }, { t1, box, 5032, 5000, 0, -1, d },
      { t2, box, 5032, 5000, 0, -1, d }, { t2, box, 5052, 5000, 0, -1, d },
    }, 1e-12)
  end)

  describe('touching is not colliding: a pair the push slides along gives no points', function()
    -- the tile [0, 32] x [0, 32] and a wall [32, 64] x [-100, 32] beside it; the box
    -- [12, 32 + e] x [-30, 10] is 10 into the tile
    local function scene(e)
      local tile, wall = H.Rectangle(16, 16, 32, 32), H.Rectangle(48, -34, 32, 132)
      local box = H.Rectangle(22 + e / 2, -10, 20 + e, 40)
      return tile, wall, box, S.triking(T.Collider(tile, wall), box)
    end

    it('e = 0: the box touches the wall, before and after the push up; only the tile\'s points', function()
      local tile, _, box, m = scene(0)
      near(m.x, 0, 0)
      near(m.y, -10, 0)
      expectPoints(S.ite(m), { { tile, box, 12, 0, 0, -1, 10 }, { tile, box, 32, 0, 0, -1, 10 } })
    end)

    it('turned, where round-off leaves the box a hair into the wall or off it: still no wall points', function()
      -- the same scene turned about the origin by many angles and moved far out: the push is
      -- along the tile's normal, square to the wall's but for round-off
      local count = 0
      for k = 1, 90 do
        local a = k * 0.0698
        local c, s = math.cos(a), math.sin(a)
        local ox, oy = 1000 + k * 37.1, -2000 + k * 11.3
        local function at(x, y) return ox + x * c - y * s, oy + x * s + y * c end
        local tx, ty = at(16, 16)
        local wx, wy = at(48, -34)
        local bx, by = at(22, -10)
        local tile, wall = H.Rectangle(tx, ty, 32, 32, a), H.Rectangle(wx, wy, 32, 132, a)
        local box = H.Rectangle(bx, by, 20, 40, a)
        local m = S.triking(T.Collider(tile, wall), box)
        local cts = S.ite(m)
        for i = 1, cts.count do
          assert(cts[i].colliderShape == tile,
            ('angle %.17g: a point on the wall, depth %.17g'):format(a, cts[i].depth))
          count = count + 1
        end
      end
      assert.equals(180, count)
    end)

    for _, e in ipairs({ 1e-3, 1e-6 }) do
      it(('e = %g: e into the wall; the push (-e, -10), the wall\'s points e deep'):format(e), function()
        -- moved, the box [12 - e, 32] x [-40, 0] lies on the tile's top (x from 12 - e to 32)
        -- and against the wall's face x = 32 (y from -40 to 0; normal (-1, 0), depth e)
        local tile, wall, box, m = scene(e)
        near(m.x, -e, 1e-12)
        near(m.y, -10)
        expectPoints(S.ite(m), {
          { tile, box, 12 - e, 0, 0, -1, 10 }, { tile, box, 32, 0, 0, -1, 10 },
          { wall, box, 32, -40, -1, 0, e }, { wall, box, 32, 0, -1, 0, e },
        }, 1e-9)
      end)
    end
  end)

  it('depth is never more than the MTV\'s length, even where round-off makes n . t exceed it', function()
    -- a box resting on a row of tiles: the push is the tile's face normal times the depth,
    -- so n . t is depth * (nx^2 + ny^2), which round-off can put an ulp above the depth
    local rows = 0
    for k = 1, 200 do
      local d = 0.1 + k * 0.01237
      local a = 0.1 * k
      local c, s = math.cos(a), math.sin(a)
      local tiles = {}
      for i = 0, 2 do tiles[#tiles + 1] = H.Rectangle(100 + 20 * i * c, 100 + 20 * i * s, 20, 10, a) end
      local floor = T.Collider((table.unpack or unpack)(tiles)) -- luacheck: ignore 113 143
      -- a box on the middle tile, sunk d along the tile's normal (-sin a, cos a) turned: up
      local ux, uy = s, -c
      local box = H.Rectangle(100 + 20 * c + ux * (10 - d), 100 + 20 * s + uy * (10 - d), 10, 10, a)
      local m = S.triking(floor, box)
      local cts = S.ite(m)
      for i = 1, cts.count do
        assert(cts[i].depth <= m.depth, ('case %d: depth %.17g over the MTV\'s %.17g'):format(k, cts[i].depth, m.depth))
        if cts[i].depth == m.depth then rows = rows + 1 end
      end
    end
    assert(rows > 0, 'no point as deep as the MTV: the scenario tests nothing')
  end)

  it('keeps its ids and names the same features as the pair alone, frame after frame', function()
    -- a box sliding on the top of a floor of 3 tiles, sunk a little: per tile, the points
    -- from the tile's top face (side 0) and the box's bottom face, as S.AT of that tile and
    -- the box alone would name them
    local tiles = {}
    for i = 0, 2 do tiles[#tiles + 1] = H.Rectangle(16 + 32 * i, 16, 32, 32) end
    local floor = T.Collider((table.unpack or unpack)(tiles)) -- luacheck: ignore 113 143
    local box = H.Rectangle(20, -4.9, 10, 10)
    local out, compared, corners = {}, 0, 0
    for frame = 1, 60 do
      box:translate(1, 0)
      local m = S.triking(floor, box)
      local c = S.ite(m, out)
      for i = 1, c.count do
        local p = c[i]
        local single = S.ite(S.AT(p.colliderShape, box))
        if single then
          local same = false
          for j = 1, single.count do if single[j].id == p.id then same = true end end
          assert(same, ('frame %d: point %d id %.0f is not the pair\'s own'):format(frame, i, p.id))
          compared = compared + 1
        else
          -- (the box's side exactly on a seam, x = 32 or 64: the next tile only touches it;
          -- after the push up its corner rests on that tile's corner: one point there)
          local bx0, _, bx1 = box:getBounds()
          assert(frame % 32 == 7 or frame % 32 == 17, ('frame %d: a point on a tile the box is not in'):format(frame))
          local seam = (frame % 32 == 7) and bx1 or bx0 -- (its right side on a seam, or its left)
          assert(seam == 32 or seam == 64)
          near(p.x, seam)
          near(p.y, 0)
          near(p.depth, 0.1, 1e-12) -- (the box sunk 0.1: its bottom at y = -4.9 + 5)
          corners = corners + 1
        end
      end
    end
    assert(compared > 100 and corners == 4, ('%d points compared, %d corners'):format(compared, corners))
  end)
end)
