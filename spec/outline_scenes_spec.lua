-- What a game sees when S.triking answers for whole bodies: the MTV is the shortest
-- translation that separates all of one body's members from all of the other's (the
-- outline rule), not the deepest MTV of a single pair of members. Each scene is played
-- through the public API as a LÖVE game would: push the moving body by the MTV, and
-- remove the part of its velocity that goes into the surface.
--   * a circle inside a concave L settles in one push, by the nearest way out of the L,
--     never across the diagonal the decomposition added between its pieces;
--   * a box dropped into the inner corner of an L and of a U comes to rest there, touching
--     the walls, and is never pushed through one;
--   * a box sinking into a floor of touching tiles is pushed straight up at every offset,
--     at any sink depth up to half its height.
local S = require('strike')
local expect = require('spec.helpers.expect')
local near = expect.near
local H, T = S.hapes, S.trikers
local abs, sqrt = math.abs, math.sqrt

-- y grows downward (LÖVE): "up" is -y.

describe('a circle inside a concave L', function()
  -- The issue's L: a horizontal arm [0, 100] x [0, 20] and a vertical one [0, 20] x [0, 100],
  -- with its inner corner at (20, 20). Its decomposition adds a diagonal between the
  -- pieces from (0, 0) to (20, 20).
  local function theL() return T.Concave(0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100) end
  local R = 3

  -- The MTV of S.triking(L, circle) must be (ex, ey) (one of several, when they tie) to
  -- 1e-9, a unit normal along it, and the other order must give its opposite.
  local function expectMTV(m, alternatives, what)
    assert(m, what .. ': no collision')
    for _, e in ipairs(alternatives) do
      local ex, ey = e[1], e[2]
      if abs(m.x - ex) <= 1e-9 and abs(m.y - ey) <= 1e-9 then
        local d = sqrt(ex * ex + ey * ey)
        near(m.depth, d, 1e-9, what .. ': depth')
        near(m.nx, ex / d, 1e-12, what .. ': nx')
        near(m.ny, ey / d, 1e-12, what .. ': ny')
        return e
      end
    end
    local want = {}
    for i, e in ipairs(alternatives) do want[i] = ('(%.17g, %.17g)'):format(e[1], e[2]) end
    assert(false, ('%s: MTV (%.17g, %.17g) depth %.17g, expected %s'):format(what, m.x, m.y, m.depth,
      table.concat(want, ' or ')))
  end

  -- After one push by `m`, the pair no longer collides. A diagonal push is a rounded
  -- product (nx * depth), so it may leave the circle 1e-15 into the wall: an overlap below
  -- 1e-9 counts as touching there; an axis-aligned push must leave it exactly touching.
  local function expectSeparated(m, what, slack)
    assert(not m or (slack and m.depth <= 1e-9),
      ('%s: still colliding after one push: MTV (%.17g, %.17g) depth %.17g'):format(what, m and m.x or 0,
        m and m.y or 0, m and m.depth or 0))
  end

  it('is pushed out of the issue\'s corner (10, 10) in one step, by 13 px through an outer wall', function()
    -- From (10, 10) the outline edges x = 0 and y = 0 are 10 away, so the circle leaves by
    -- 10 + 3 = 13 through either: (-13, 0) or (0, -13), an exact tie. The inner corner
    -- needs (13, 13) (the circle must reach (23, 23)), the far walls 93. Today the circle
    -- is pushed 3 px across the diagonal to (12.12, 7.88), then 6 px back, forever.
    local L, c = theL(), H.Circle(10, 10, R)
    local m = S.triking(L, c)
    local e = expectMTV(m, { { -13, 0 }, { 0, -13 } }, 'S.triking(L, circle)')
    c:translate(m.x, m.y)
    local x, y = c:getCentroid()
    assert.same({ 10 + e[1], 10 + e[2] }, { x, y }) -- (-3, 10) or (10, -3), exactly
    expectSeparated(S.triking(L, c), 'S.triking(L, circle)')
    expectSeparated(S.triking(c, L), 'S.triking(circle, L)')

    -- the other order: moving the L by +mtv separates, so the vector is the opposite one
    L, c = theL(), H.Circle(10, 10, R)
    m = S.triking(c, L)
    expectMTV(m, { { 13, 0 }, { 0, 13 } }, 'S.triking(circle, L)')
    L:translate(m.x, m.y)
    expectSeparated(S.triking(c, L), 'S.triking(circle, L), the L moved')
  end)

  it('leaves by the nearest outline edge from anywhere around the added diagonal, in one step', function()
    local s = R / sqrt(2) -- the issue's two positions are (10 +- s, 10 -+ s)
    local cases = {
      -- centre, then the MTV: the nearest edge of the outline, not of a piece
      { 12, 8, 0, -11 },               -- the top wall is 8 away: up by 8 + 3
      { 8, 12, -11, 0 },               -- the left wall is 8 away
      { 10 + s, 10 - s, 0, -(13 - s) }, -- where today's first push puts the circle
      { 10 - s, 10 + s, -(13 - s), 0 }, -- and where its second one does
      { 15, 5, 0, -8 },
      { 5, 15, -8, 0 },
      -- nearer the inner corner than the outer walls: out into the free quadrant, until the
      -- circle clears both edges that meet there (its centre at (23, 23)), diagonally
      { 16, 16, 7, 7 },
      { 18, 18, 5, 5 },
      { 22, 22, 1, 1 },                -- (already past the corner: 2 from both edges)
      { 60, 12, 0, 11 },               -- in the horizontal arm: down through its inner edge
    }
    for _, case in ipairs(cases) do
      local cx, cy, ex, ey = case[1], case[2], case[3], case[4]
      local what = ('circle at (%.17g, %.17g)'):format(cx, cy)
      local L, c = theL(), H.Circle(cx, cy, R)
      local m = S.triking(L, c)
      expectMTV(m, { { ex, ey } }, what)
      c:translate(m.x, m.y)
      expectSeparated(S.triking(L, c), what, ex ~= 0 and ey ~= 0)
      m = S.triking(H.Circle(cx, cy, R), L)
      expectMTV(m, { { -ex, -ey } }, what .. ' (the other order)')
    end
  end)

  it('is not pushed back and forth: a game loop settles it in one push', function()
    local L, c = theL(), H.Circle(10, 10, R)
    local pushes = 0
    for _ = 1, 10 do
      local m = S.triking(L, c)
      if not m then break end
      c:translate(m.x, m.y)
      pushes = pushes + 1
    end
    local x, y = c:getCentroid()
    assert(pushes == 1, ('%d pushes, the circle ends at (%.17g, %.17g)'):format(pushes, x, y))
  end)
end)

describe('a box dropped into an inner corner', function()
  -- Static level geometry, y down: an L (a wall x in [0, 20] standing on a floor y in
  -- [80, 100]; inner corner (20, 80)) and a U (walls x in [0, 20] and [80, 100] on the same
  -- floor; inner corners (20, 80) and (80, 80)).
  local function levelL() return T.Concave(0, 0, 20, 0, 20, 80, 100, 80, 100, 100, 0, 100) end
  local function levelU() return T.Concave(0, 0, 20, 0, 20, 80, 80, 80, 80, 0, 100, 0, 100, 100, 0, 100) end
  local WALL_L, WALL_R, FLOOR = 20, 80, 80
  -- (the drops below move at most 7 px a frame, well under the walls' 20: no tunnelling)
  local DT, GRAVITY = 1 / 60, 1000 -- s, px/s^2
  local FRAMES, REST, PUSHES = 240, 30, 8
  local TOL = 1e-9

  -- A LÖVE-style frame loop: integrate the velocity, move, then push the box out by the
  -- MTV of S.triking(level, box) until it no longer collides, removing the part of the
  -- velocity that goes into the surface at each push. Returns the box's bounds after each
  -- frame, or raises with the frame, when a frame ends with the box still in the level, or
  -- outside the region `inside(x0, y0, x1, y1)` accepts.
  local function drop(level, box, vx, inside, what)
    local vy = 0
    local frames = {}
    for f = 1, FRAMES do
      vy = vy + GRAVITY * DT
      box:translate(vx * DT, vy * DT)
      local m = S.triking(level, box)
      local pushes = 0
      while m and m.depth > TOL and pushes < PUSHES do
        box:translate(m.x, m.y)
        local vn = vx * m.nx + vy * m.ny
        if vn < 0 then vx, vy = vx - vn * m.nx, vy - vn * m.ny end
        pushes = pushes + 1
        m = S.triking(level, box)
      end
      local x0, y0, x1, y1 = box:getBounds()
      assert(not m or m.depth <= TOL, ('%s: frame %d: still colliding after %d pushes (depth %.17g), box at'
        .. ' [%.17g, %.17g] x [%.17g, %.17g]'):format(what, f, pushes, m and m.depth or 0, x0, x1, y0, y1))
      assert(inside(x0, y0, x1, y1), ('%s: frame %d: pushed out of the open region, box at [%.17g, %.17g] x'
        .. ' [%.17g, %.17g]'):format(what, f, x0, x1, y0, y1))
      frames[f] = { x0, y0, x1, y1 }
    end
    return frames
  end

  -- The box ends at rest: it moved less than TOL over the last REST frames, and rests
  -- exactly on the floor against the wall `side` names ('left': its left side on x = WALL_L,
  -- 'right': its right side on x = WALL_R, nil: no wall).
  local function expectRest(frames, side, what)
    local last = frames[#frames]
    for f = #frames - REST, #frames - 1 do
      for k = 1, 4 do
        assert(abs(frames[f][k] - last[k]) <= TOL, ('%s: still moving at frame %d: bound %d is %.17g, then %.17g')
          :format(what, f, k, frames[f][k], last[k]))
      end
    end
    near(last[4], FLOOR, TOL, what .. ': bottom on the floor')
    if side == 'left' then near(last[1], WALL_L, TOL, what .. ': left side on the wall') end
    if side == 'right' then near(last[3], WALL_R, TOL, what .. ': right side on the wall') end
  end

  local function insideL(x0, _, _, y1) return x0 >= WALL_L - TOL and y1 <= FLOOR + TOL end
  local function insideU(x0, _, x1, y1) return x0 >= WALL_L - TOL and x1 <= WALL_R + TOL and y1 <= FLOOR + TOL end

  -- Drops: box sizes, how far from the wall the box starts (its top at y = TOP) and how fast
  -- it moves toward the wall. Most reach the wall in the air or land first and slide into
  -- the corner; some reach the wall and the floor in the same frame (with 7 px and 400 px/s:
  -- the true MTV there is diagonal, into the corner).
  local TOP = 20
  local SIZES, GAPS, SPEEDS = { 6, 16, 30 }, { 0.5, 7, 23 }, { 40, 150, 400 }

  it('an L: the box comes to rest in the corner, on the floor and against the wall', function()
    for _, size in ipairs(SIZES) do
      for _, gap in ipairs(GAPS) do
        for _, speed in ipairs(SPEEDS) do
          local what = ('L, box %g, %g from the wall, %g px/s'):format(size, gap, speed)
          local box = H.Rectangle(WALL_L + gap + size / 2, TOP + size / 2, size, size)
          expectRest(drop(levelL(), box, -speed, insideL, what), 'left', what)
        end
      end
    end
  end)

  it('a U: the box comes to rest in either corner, and at the bottom when dropped straight', function()
    for _, size in ipairs(SIZES) do
      for _, gap in ipairs(GAPS) do
        for _, speed in ipairs(SPEEDS) do
          local what = ('U, box %g, %g from the left wall, %g px/s left'):format(size, gap, speed)
          local box = H.Rectangle(WALL_L + gap + size / 2, TOP + size / 2, size, size)
          expectRest(drop(levelU(), box, -speed, insideU, what), 'left', what)
          what = ('U, box %g, %g from the right wall, %g px/s right'):format(size, gap, speed)
          box = H.Rectangle(WALL_R - gap - size / 2, TOP + size / 2, size, size)
          expectRest(drop(levelU(), box, speed, insideU, what), 'right', what)
        end
      end
      -- straight down into the middle: it lands where it was dropped
      local what = ('U, box %g dropped straight'):format(size)
      local frames = drop(levelU(), H.Rectangle(50, TOP + size / 2, size, size), 0, insideU, what)
      expectRest(frames, nil, what)
      near(frames[#frames][1], 50 - size / 2, TOL, what .. ': left side')
    end
  end)

  it('a box as wide as the U\'s gap falls to the bottom without catching on the walls', function()
    local frames = drop(levelU(), H.Rectangle(50, 30, 60, 20), 0, insideU, 'U, box 60 wide')
    expectRest(frames, 'left', 'U, box 60 wide')
    near(frames[#frames][3], WALL_R, TOL, 'U, box 60 wide: right side on the wall')
  end)
end)

describe('a box sinking into a floor of touching tiles', function()
  -- 20 square tiles of 32 px in one collider, their tops on y = 0; a box 32 wide and 40
  -- tall (the tile's width: it spans a seam at most offsets). The issue's 321 drops: the
  -- box's left side from the seam at x = 320 to the next one, at 352, in steps of 0.1.
  -- Every translation that takes the box out sideways crosses the whole floor; the way out
  -- is straight up, by the sink.
  local TILE, N, W, BH = 32, 20, 32, 40
  local SEAM, DROPS = 320, 321

  local function floor()
    local f = T.Collider()
    for i = 0, N - 1 do f:add(H.Rectangle((i + 0.5) * TILE, TILE / 2, TILE, TILE)) end
    return f
  end

  -- The box with its left side at SEAM + k / 10 and its bottom `sink` below the floor's top.
  local function box(k, sink) return H.Rectangle(SEAM + k / 10 + W / 2, sink - BH / 2, W, BH) end

  -- Drop the box at every offset with this sink and check the MTV of S.triking(f, box) (or
  -- of S.triking(box, f) when `reversed`: the same vector, opposite): purely vertical,
  -- pushing the box up by the sink, after which it rests on the floor. Returns the number
  -- of drops that fail and a description of the first.
  local function drops(f, sink, reversed)
    local bad, first = 0, nil
    for k = 0, DROPS - 1 do
      local b = box(k, sink)
      local m = reversed and S.triking(b, f) or S.triking(f, b)
      local sign = reversed and -1 or 1
      local ok = m and abs(m.nx) <= 1e-12 and abs(m.depth - sink) <= 1e-9 and abs(sign * m.y + sink) <= 1e-9
      if ok then
        b:translate(sign * m.x, sign * m.y)
        local again = S.triking(f, b)
        ok = not again
      end
      if not ok then
        bad = bad + 1
        first = first or (m and ('offset %.1f: MTV (%.17g, %.17g) depth %.17g'):format(k / 10, m.x, m.y, m.depth)
          or ('offset %.1f: no collision'):format(k / 10))
      end
    end
    return bad, first
  end

  it('at 20 px of sink (half its height), all 321 drops are pushed straight up, in either order', function()
    local f = floor()
    for _, reversed in ipairs({ false, true }) do
      local bad, first = drops(f, 20, reversed)
      assert(bad == 0, ('%s: %d of %d drops pushed sideways or not out; first at %s')
        :format(reversed and 'S.triking(box, floor)' or 'S.triking(floor, box)', bad, DROPS, tostring(first)))
    end
  end)

  it('at any sink depth from a hair to half its height, every drop is pushed straight up by the sink', function()
    local f = floor()
    local sinks = { 2 ^ -30, 2 ^ -10 }
    for i = 1, 2 * BH / 2 do sinks[#sinks + 1] = i / 2 end -- 0.5, 1, ..., 20
    local failed = {}
    for _, sink in ipairs(sinks) do
      local bad, first = drops(f, sink, false)
      if bad > 0 then failed[#failed + 1] = ('sink %g: %d of %d (first at %s)'):format(sink, bad, DROPS, first) end
    end
    assert(#failed == 0, ('drops pushed sideways or not out, at %d of %d sink depths:\n  %s')
      :format(#failed, #sinks, table.concat(failed, '\n  ')))
  end)
end)
