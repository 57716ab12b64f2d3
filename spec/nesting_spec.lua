-- Colliders nested to any depth (docs/shapes.md, "Colliders: S.trikers"): every walk over the
-- tree is a loop with a stack of its own, so a chain of colliders 20,000 deep (LuaJIT's C stack
-- overflowed at 5,000 when the walks recursed) answers every call, on every VM, as the same
-- leaves held by one flat collider do.
local S = require('strike')
local expect = require('spec.helpers.expect')
local H, T = S.hapes, S.trikers

local DEPTH = 20000
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

-- A chain of `depth` colliders, each holding the next; the innermost holds the shapes given.
-- Returns the outermost and the innermost.
local function chain(depth, ...)
  local bottom = T.Collider(...)
  local c = bottom
  for _ = 2, depth do c = T.Collider(c) end
  return c, bottom
end

-- The number of colliders above a shape or collider.
local function depthOf(node)
  local d, p = 0, node:getParent()
  while p do
    d = d + 1
    p = p:getParent()
  end
  return d
end

local function leaves(body)
  local list = {}
  for s in body:elems() do list[#list + 1] = s end
  return list
end

-- The same leaves, copied into one flat collider.
local function flatOf(body)
  local copies = {}
  for i, s in ipairs(leaves(body)) do copies[i] = s:copy() end
  return T.Collider(unpack(copies))
end

local function near(a, b, what, scale)
  expect.near(a, b, 1e-9 * (scale or 1), what)
end

local function nearList(a, b, what, scale)
  assert.equals(#b, #a, what)
  for i = 1, #b do
    if type(b[i]) == 'number' then
      near(a[i], b[i], what .. ' value ' .. i, scale)
    else
      assert.equals(b[i], a[i], what .. ' value ' .. i)
    end
  end
end

-- A hit's numbers, in order, or { false }.
local function hitOf(h, ...)
  if not h then return { false } end
  local list = {}
  for _, k in ipairs({ ... }) do list[#list + 1] = h[k] end
  return list
end

-- Every answer of `deep` is the flat collider's (scale: the size of the scene, for the
-- tolerance of sums taken in another order).
local function sameAnswers(deep, flat, scale)
  scale = scale or 100
  nearList({ deep:getCentroid() }, { flat:getCentroid() }, 'centroid', scale)
  near(deep:getArea(), flat:getArea(), 'area', scale * scale)
  near(deep:getRadius(), flat:getRadius(), 'radius', scale)
  nearList({ deep:getBbox() }, { flat:getBbox() }, 'bbox', scale)
  nearList({ deep:getBounds() }, { flat:getBounds() }, 'bounds', scale)
  assert.equals(flat:getShapeCount(), deep:getShapeCount())
  nearList({ deep:project(0.6, 0.8) }, { flat:project(0.6, 0.8) }, 'project', scale)
  local x0, y0, x1, y1 = flat:getBounds()
  for i = 0, 6 do
    for j = 0, 6 do
      local x, y = x0 + (x1 - x0) * i / 6, y0 + (y1 - y0) * j / 6
      assert.equals(flat:containsPoint(x, y), deep:containsPoint(x, y), ('containsPoint %g %g'):format(x, y))
    end
  end
  local cx, cy = flat:getCentroid()
  for a = 0, 5 do
    local ux, uy = math.cos(a + 0.3), math.sin(a + 0.3)
    local ox, oy = cx - 3 * scale * ux, cy - 3 * scale * uy
    local dd, dx, dy, dnx, dny = deep:rayCast(ox, oy, ux, uy)
    local fd, fx, fy, fnx, fny = flat:rayCast(ox, oy, ux, uy)
    nearList({ dd or false, dx, dy, dnx, dny }, { fd or false, fx, fy, fnx, fny }, 'rayCast', scale)
    assert.equals(flat:rayIntersects(ox, oy, ux, uy), deep:rayIntersects(ox, oy, ux, uy))
    local sd, sx, sy, snx, sny = deep:segmentCast(ox, oy, cx, cy)
    local td, tx, ty, tnx, tny = flat:segmentCast(ox, oy, cx, cy)
    nearList({ sd or false, sx, sy, snx, sny }, { td or false, tx, ty, tnx, tny }, 'segmentCast', scale)
    local n = 0
    for _ in pairs(deep:rayIntersections(ox, oy, ux, uy) or {}) do n = n + 1 end
    local m = 0
    for _ in pairs(flat:rayIntersections(ox, oy, ux, uy) or {}) do m = m + 1 end
    assert.equals(m, n, 'rayIntersections')
  end
  -- against probes about it: S.triking both ways, S.ite, S.weep, S.eparation, S.aabb, S.ircle
  for _, p in ipairs({ { 0.2, 0.1 }, { 0.5, 0.5 }, { 0.9, 0.3 }, { 1.4, 0.5 } }) do
    local probe = T.Rectangle(x0 + (x1 - x0) * p[1], y0 + (y1 - y0) * p[2], 4, 3, 0.2)
    for _, order in ipairs({ true, false }) do
      local dm = order and S.triking(deep, probe) or S.triking(probe, deep)
      local fm = order and S.triking(flat, probe) or S.triking(probe, flat)
      nearList(hitOf(dm, 'x', 'y', 'depth'), hitOf(fm, 'x', 'y', 'depth'), 'triking', scale)
      if fm then
        local dc, fc = S.ite(dm), S.ite(fm)
        assert.equals(fc.count, dc.count, 'ite count')
        for k = 1, fc.count do nearList({ dc[k].x, dc[k].y }, { fc[k].x, fc[k].y }, 'ite', scale) end
      end
    end
    local px, py = probe:getCentroid()
    nearList(hitOf(S.weep(probe, (cx - px) * 2, (cy - py) * 2, deep), 't', 'x', 'y', 'nx', 'ny'),
      hitOf(S.weep(probe, (cx - px) * 2, (cy - py) * 2, flat), 't', 'x', 'y', 'nx', 'ny'), 'weep', scale)
    nearList(hitOf(S.weep(deep, px - cx, py - cy, probe, 0.4), 't', 'x', 'y', 'nx', 'ny'),
      hitOf(S.weep(flat, px - cx, py - cy, probe, 0.4), 't', 'x', 'y', 'nx', 'ny'), 'weep turning', scale)
    nearList({ S.eparation(deep, probe) }, { S.eparation(flat, probe) }, 'eparation', scale)
    assert.equals(S.aabb(flat, probe), S.aabb(deep, probe))
    assert.equals(S.ircle(flat, probe), S.ircle(deep, probe))
  end
end

describe('colliders nested 20,000 deep', function()
  it('build, and answer every getter and query as the same leaves in one flat collider', function()
    local deep, bottom = chain(DEPTH, H.Rectangle(0, 0, 10, 6), H.Circle(8, 0, 3), H.Edge(-6, 5, 6, 9))
    assert.equals(DEPTH, depthOf((bottom:unpack())))
    assert.equals(deep, (bottom:unpack()):getRoot())
    assert.equals(deep, bottom:getRoot())
    assert.equals(3, deep:getShapeCount())
    assert.equals(3, #leaves(deep))
    local n = 0
    for parent, shape, index in deep:ipairs() do
      n = n + 1
      assert.equals(bottom, parent)
      assert.equals(shape, select(index, bottom:unpack()))
    end
    assert.equals(3, n)
    sameAnswers(deep, flatOf(deep))
  end)

  it('every transform of the outermost, of one in the middle and of a leaf at the bottom', function()
    local deep, bottom = chain(DEPTH, H.Rectangle(0, 0, 10, 6), H.Circle(8, 0, 3))
    local flat = flatOf(deep)
    local steps = {
      function(b) return b:translate(3, -2) end,
      function(b) return b:rotate(0.4) end,
      function(b) return b:rotate(-0.2, 5, 7) end,
      function(b) return b:scale(1.5) end,
      function(b) return b:scale(0.8, -3, 2) end,
      function(b) return b:translateTo(20, 10) end,
      function(b) return b:rotateTo(1) end,
    }
    -- (and the caches of the colliders deep inside, which a translation shifts where it
    -- keeps them: the same as their leaves' own, fresh)
    local mid = deep
    for _ = 1, DEPTH / 2 do mid = mid:unpack() end
    local function inside(what)
      for _, c in ipairs({ mid, bottom }) do
        local fresh = flatOf(c)
        nearList({ c:getBbox() }, { fresh:getBbox() }, what .. ': bbox inside', 100)
        nearList({ c:getCentroid() }, { fresh:getCentroid() }, what .. ': centroid inside', 100)
        near(c:getArea(), fresh:getArea(), what .. ': area inside', 1e4)
        near(c:getAngle(), deep:getAngle(), what .. ': angle inside')
      end
    end
    inside('at first')
    for i, step in ipairs(steps) do
      step(deep)
      step(flat)
      sameAnswers(deep, flat)
      near(deep:getAngle(), flat:getAngle(), 'angle after step ' .. i)
      inside('step ' .. i)
    end
    -- a collider in the middle holds every leaf below: moving it moves them all
    assert.equals(DEPTH / 2, depthOf(mid))
    mid:rotate(0.3, 4, 4)
    flat:rotate(0.3, 4, 4)
    mid:translate(-1, 2)
    flat:translate(-1, 2)
    sameAnswers(deep, flat)
    near(mid:getAngle(), bottom:getAngle(), 'the angle of every collider below')
    -- a leaf at the bottom, alone
    local dl, fl = bottom:unpack(), flat:unpack()
    dl:translate(2, 2)
    fl:translate(2, 2)
    sameAnswers(deep, flat)
    dl:rotate(0.5)
    fl:rotate(0.5)
    sameAnswers(deep, flat)
  end)

  it('members added and removed at the bottom, and in the middle', function()
    local deep, bottom = chain(DEPTH, H.Rectangle(0, 0, 10, 6))
    local flat = flatOf(deep)
    sameAnswers(deep, flat)
    bottom:add(H.Circle(9, 1, 4), H.Rectangle(-8, 0, 4, 4))
    flat:add(H.Circle(9, 1, 4), H.Rectangle(-8, 0, 4, 4))
    sameAnswers(deep, flat)
    local gone = bottom:remove(2)
    flat:remove(2)
    assert.is_nil(gone:getParent())
    sameAnswers(deep, flat)
    -- a collider 20,000 deep of its own, added in the middle
    local mid = deep
    for _ = 1, DEPTH / 4 do mid = mid:unpack() end
    local other = chain(DEPTH, H.Circle(-20, -5, 2))
    mid:add(other)
    flat:add(H.Circle(-20, -5, 2))
    assert.equals(deep, other:getRoot())
    assert.equals(DEPTH / 4 + 1 + DEPTH, depthOf(leaves(other)[1]))
    sameAnswers(deep, flat)
    mid:remove(2)
    flat:remove(3)
    sameAnswers(deep, flat)
    assert.equals(other, leaves(other)[1]:getRoot())
  end)

  it('copy and consolidate', function()
    local deep = chain(DEPTH, H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10), H.Circle(30, 0, 4))
    local flat = flatOf(deep)
    local copy = deep:copy()
    sameAnswers(copy, flat)
    assert.equals(DEPTH, depthOf(leaves(copy)[1]))
    assert.equals(copy, leaves(copy)[1]:getRoot())
    assert.are_not.equal(leaves(deep)[1], leaves(copy)[1])
    local moved = deep:copy(50, 60, 0.5)
    flat:translateTo(50, 60)
    flat:rotateTo(0.5)
    sameAnswers(moved, flat)
    -- the two squares at the bottom merge into one rectangle
    deep:consolidate()
    assert.equals(2, deep:getShapeCount())
    local f2 = flatOf(copy):consolidate()
    assert.equals(2, f2:getShapeCount())
    sameAnswers(deep, f2)
  end)

  it('in a space: add, queries, collisions and events, moves of the body and of its leaf, remove', function()
    local space = S.pace()
    local events = {}
    space:on('begin', function(a, b) events[#events + 1] = { 'begin', a, b } end)
    space:on('end', function(a, b) events[#events + 1] = { 'end', a, b } end)
    local deep, bottom = chain(DEPTH, H.Rectangle(0, 0, 10, 6), H.Circle(8, 0, 3))
    local wall = T.Rectangle(40, 0, 4, 40)
    space:add(deep)
    space:add(wall)
    assert.equals(deep, space:queryPoint(1, 1)[1])
    assert.equals(1, #space:queryRect(-1, -1, 2, 2))
    assert.equals(deep, space:queryShape(T.Circle(0, 0, 1))[1])
    assert.equals(deep, (space:rayCast(-50, 0, 1, 0)))
    assert.equals(2, #space:rayCastAll(-50, 0, 1, 0))
    assert.equals(0, #space:check(deep))
    local _, n = space:collisions()
    assert.equals(0, n)
    -- the leaf at the bottom moves: the space sees it at once
    local leaf = bottom:unpack()
    leaf:translate(35, 0)
    assert.equals(deep, space:queryPoint(36, 0)[1])
    local list
    list, n = space:collisions()
    assert.equals(1, n)
    assert.equals(deep, list[1].a)
    assert.same({ 'begin', deep, wall }, events[1])
    leaf:translate(-35, 0)
    _, n = space:collisions()
    assert.equals(0, n)
    assert.same({ 'end', deep, wall }, events[2])
    -- moves and casts
    local hit = space:cast(deep, 50, 0)
    assert.equals(wall, hit.body)
    local x, y, cols, count = space:move(deep, 50, 0)
    assert.equals(1, count)
    assert.equals(wall, cols[1].other)
    expect.near(y, 0, 1e-9)
    local _, _, maxx = deep:getBounds()
    assert.is_true(maxx < 38 and maxx > 38 - 1e-3, 'stopped a skin short of the wall: ' .. maxx)
    assert.is_true(x > 0)
    assert.is_false(S.triking(deep, wall))
    -- members added and removed at the bottom are seen too
    bottom:add(H.Circle(40, 0, 1))
    _, n = space:collisions()
    assert.equals(1, n)
    bottom:remove(3)
    _, n = space:collisions()
    assert.equals(0, n)
    space:remove(deep)
    assert.is_false(space:has(deep))
    assert.equals(0, #space:queryPoint(1, 1))
  end)

  it('a wide and deep mix: chains of thousands, leaves at every thousandth level, a shallow part', function()
    local root = T.Collider(H.Circle(-30, 0, 2), T.Collider(H.Rectangle(-20, 0, 3, 3)))
    local flat = T.Collider(H.Circle(-30, 0, 2), H.Rectangle(-20, 0, 3, 3))
    -- (built from the bottom up: adding a member n deep walks up n colliders, to refuse a
    -- cycle and to tell every enclosing one that it changed)
    for b = 1, 3 do
      local c = T.Collider()
      for level = 7000, 1, -1 do
        if level % 1000 == 0 then
          local x, y = b * 15, level / 100
          c:add(H.Rectangle(x, y, 4, 2, 0.1 * b))
          flat:add(H.Rectangle(x, y, 4, 2, 0.1 * b))
        end
        if level > 1 then c = T.Collider(c) end
      end
      root:add(c)
    end
    assert.equals(2 + 21, root:getShapeCount())
    sameAnswers(root, flat)
    root:rotate(0.25)
    flat:rotate(0.25)
    root:translate(-4, 9)
    flat:translate(-4, 9)
    sameAnswers(root, flat)
    -- a leaf 5,001 deep leaves its chain
    local deepLeaf
    for _, s in ipairs(leaves(root)) do
      if depthOf(s) == 5001 then deepLeaf = s end
    end
    assert.is_not_nil(deepLeaf)
    local p = deepLeaf:getParent()
    local idx
    for i = 1, select('#', p:unpack()) do
      if select(i, p:unpack()) == deepLeaf then idx = i end
    end
    p:remove(idx)
    for i, s in ipairs(leaves(flat)) do
      local x, y = s:getCentroid()
      local lx, ly = deepLeaf:getCentroid()
      if x == lx and y == ly then flat:remove(i) end
    end
    sameAnswers(root, flat)
    assert.equals(22, root:getShapeCount())
    local copy = root:copy()
    sameAnswers(copy, flat)
  end)

  it('a field strike reserves, changed deep down, is named by the same walks', function()
    local deep, bottom = chain(DEPTH, H.Rectangle(0, 0, 10, 6), H.Rectangle(12, 0, 10, 6))
    local leaf = bottom:unpack()
    leaf._kind = 'orc'
    expect.raisesAt(function() S.triking(deep, T.Circle(0, 0, 2)) end,
      'strike.triking: argument 1 holds a shape whose field _kind was changed (now string "orc")')
    leaf._kind = 'polygon'
    deep:getArea()
    local mid = deep
    for _ = 1, DEPTH / 2 do mid = mid:unpack() end
    mid._shapes = {}
    leaf:translate(1, 0)
    expect.raisesAt(function() deep:getArea() end, 'strike: the collider\'s field _shapes was changed (now table)')
    -- the walk the error stopped lets go of what it held, and the next walks start afresh
    local weak = setmetatable({ deep }, { __mode = 'v' })
    deep, bottom, leaf, mid = nil, nil, nil, nil -- luacheck: ignore 311
    collectgarbage('collect')
    collectgarbage('collect')
    assert.is_nil(weak[1])
    local again = chain(50, H.Rectangle(0, 0, 10, 6))
    assert.equals(60, again:getArea())
  end)

  it('draws every leaf', function()
    local drawn = 0
    rawset(_G, 'love', { graphics = { polygon = function() drawn = drawn + 1 end, line = function() end,
      circle = function() end, getColor = function() return 1, 1, 1, 1 end, setColor = function() end } })
    finally(function() rawset(_G, 'love', nil) end)
    local deep = chain(DEPTH, H.Rectangle(0, 0, 10, 6), H.Rectangle(12, 0, 10, 6))
    deep:draw('fill')
    assert.equals(2, drawn)
  end)
end)
