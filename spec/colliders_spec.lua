local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local H, T = S.hapes, S.trikers
local pi = math.pi
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

local function bbox(c) return { c:getBbox() } end

describe('single-shape colliders', function()
  it('exist for every shape name and hold one shape built from the same arguments', function()
    local cases = {
      Rectangle = { 0, 0, 4, 2, 0.5 }, Circle = { 1, 2, 3 }, Edge = { 0, 0, 5, 5 },
      ConvexPolygon = { 0, 0, 4, 0, 0, 3 }, Ellipse = { 0, 0, 5, 3 }, RegularPolygon = { 0, 0, 6, 4 },
    }
    for name, args in pairs(cases) do
      local c = T[name](unpack(args))
      assert.is_true(c:is(T.Collider), name)
      assert.is_true(c:is(T[name]), name)
      assert.equals(1, select('#', c:unpack()))
      assert.equals(H[name], getmetatable((c:unpack())))
      nearList(bbox(c), { (c:unpack()):getBbox() })
    end
  end)

  it('take the shape angle, so rotateTo is absolute', function()
    local c = T.Rectangle(0, 0, 4, 2, pi / 2)
    near(c:getAngle(), pi / 2)
    c:rotateTo(0)
    nearList(bbox(c), { -2, -1, 4, 2 })
  end)

  it('report shape errors at the caller\'s line', function()
    raisesAt(function() T.Circle(0, 0) end, 'strike.Circle: radius must be a finite number > 0, got nil')
  end)
end)

describe('Collider', function()
  it('holds shapes and colliders nested to any depth', function()
    local deep = T.Collider(T.Collider(T.Collider(H.Circle(0, 0, 1))), H.Rectangle(10, 0, 2))
    assert.equals(2, deep:getShapeCount())
    local names = {}
    for s in deep:elems() do names[#names + 1] = s.name end
    assert.same({ 'Circle', 'Rectangle' }, names)
  end)

  it('aggregates area, centroid, radius and bounds', function()
    local c = T.Collider(H.Rectangle(0, 0, 2), H.Rectangle(10, 0, 2))
    assert.equals(8, c:getArea())
    nearList({ c:getCentroid() }, { 5, 0 })
    local a, x, y = c:getAreaCentroid()
    nearList({ a, x, y }, { 8, 5, 0 })
    near(c:getRadius(), math.sqrt(37))
    nearList(bbox(c), { -1, -1, 12, 2 })
    nearList({ c:project(1, 0) }, { -1, 11 })
  end)

  it('weights centroids by area, and edges-only colliders by length', function()
    local c = T.Collider(H.Rectangle(0, 0, 2), H.Rectangle(10, 0, 2, 6))
    nearList({ c:getCentroid() }, { 7.5, 0 })
    local e = T.Collider(H.Edge(0, 0, 10, 0), H.Edge(10, 0, 10, 30))
    nearList({ e:getCentroid() }, { 8.75, 11.25 })
    assert.equals(0, e:getArea())
    nearList(bbox(e), { 0, 0, 10, 30 })
  end)

  it('is empty-safe', function()
    local c = T.Collider()
    assert.equals(0, c:getArea())
    nearList({ c:getCentroid() }, { 0, 0 })
    nearList(bbox(c), { 0, 0, 0, 0 })
    assert.equals(0, c:getRadius())
    assert.equals(c, c:translate(1, 1):rotate(1):scale(2))
    -- an empty collider nested in another bounds nothing there (its own bounds are 0, 0, 0, 0)
    local outer = T.Collider(H.Rectangle(100, 50, 10, 4), T.Collider())
    nearList(bbox(outer), { 95, 48, 10, 4 })
  end)

  it('transforms every shape and returns self', function()
    local c = T.Collider(H.Rectangle(0, 0, 2), H.Circle(10, 0, 1))
    assert.equals(c, c:translate(1, 2))
    nearList({ select(2, c:unpack()):getCentroid() }, { 11, 2 })
    assert.equals(c, c:translateTo(0, 0))
    nearList({ c:getCentroid() }, { 0, 0 })
    local x1 = select(2, c:unpack()):getCentroid()
    assert.equals(c, c:rotate(pi))
    near((select(2, c:unpack()):getCentroid()), -x1)
    near(c:getAngle(), pi)
    assert.equals(c, c:rotateTo(0))
    near((select(2, c:unpack()):getCentroid()), x1)
    local area = c:getArea()
    assert.equals(c, c:scale(2))
    near(c:getArea(), 4 * area)
    near((select(2, c:unpack()):getCentroid()), 2 * x1)
    assert.equals(2, select(2, c:unpack()):getRadius())
  end)

  it('keeps nested colliders right after transforms of the outer one', function()
    local inner = T.Collider(H.Rectangle(10, 0, 2))
    local outer = T.Collider(inner, H.Rectangle(-10, 0, 2))
    outer:rotate(pi / 2, 0, 0)
    nearList({ inner:getCentroid() }, { 0, 10 })
    near(inner:getAngle(), pi / 2)
    outer:scale(2, 0, 0)
    nearList(bbox(inner), { -2, 18, 4, 4 })
    near(outer:getArea(), 32)
    local member = inner:unpack()
    member:translate(5, 0) -- moving a leaf directly updates both
    nearList({ inner:getCentroid() }, { 5, 20 })
    nearList(bbox(outer), { -2, -22, 9, 44 })
  end)

  it('rotateTo and scale compose about a reference point', function()
    local c = T.Collider(H.Circle(10, 0, 1))
    c:rotate(pi / 2, 0, 0):rotateTo(pi / 2, 0, 0)
    nearList({ c:getCentroid() }, { 0, 10 })
    c:scale(2, 0, 0):scale(2, 0, 0)
    nearList({ c:getCentroid() }, { 0, 40 })
  end)

  it('validates transform arguments', function()
    local c = T.Collider(H.Circle(0, 0, 1))
    raisesAt(function() c:translate(nil, 1) end, 'strike.Collider:translate: dx must be a finite number, got nil')
    raisesAt(function() c:translateTo(1) end, 'strike.Collider:translateTo: y must be a finite number, got nil')
    raisesAt(function() c:rotate(0 / 0) end, 'strike.Collider:rotate: angle must be a finite number, got nan')
    raisesAt(function() c:rotateTo(1, 2) end, 'strike.Collider:rotateTo: reference y must be a finite number')
    raisesAt(function() c:scale(-2) end, 'strike.Collider:scale: factor must be a finite number > 0, got -2')
    raisesAt(function() c:project(1) end, 'strike.Collider:project: ny must be a finite number, got nil')
  end)

  it('add keeps the aggregates right and rejects bad children', function()
    local c = T.Collider(H.Rectangle(0, 0, 2))
    c:add(H.Rectangle(10, 0, 2))
    assert.equals(8, c:getArea())
    nearList({ c:getCentroid() }, { 5, 0 })
    raisesAt(function() c:add(42) end, 'strike.Collider:add: argument 1 must be a strike shape or collider, got 42')
    raisesAt(function() c:add((c:unpack())) end, 'argument 1 already belongs to a collider')
    local outer = T.Collider(c)
    raisesAt(function() c:add(outer) end, 'strike.Collider:add: argument 1 would contain itself')
  end)

  it('remove takes indices as numbered before the call and returns the children', function()
    local a, b, c3, d = H.Circle(0, 0, 1), H.Circle(10, 0, 1), H.Circle(20, 0, 1), H.Circle(30, 0, 1)
    local c = T.Collider(a, b, c3, d)
    local r1, r2 = c:remove(1, 2)
    assert.equals(a, r1)
    assert.equals(b, r2)
    assert.same({ c3, d }, { c:unpack() })
    assert.is_nil(a:getParent())
    nearList({ c:getCentroid() }, { 25, 0 })
    nearList(bbox(c), { 19, -1, 12, 2 })
    raisesAt(function() c:remove(3) end, 'strike.Collider:remove: index must be an integer from 1 to 2, got 3')
    raisesAt(function() c:remove(1, 1) end, 'strike.Collider:remove: index 1 given twice')
  end)

  it('unpack returns the direct children', function()
    local a, b = H.Circle(0, 0, 1), T.Collider(H.Circle(5, 0, 1))
    local x, y = T.Collider(a, b):unpack()
    assert.equals(a, x)
    assert.equals(b, y)
  end)

  it('copy is an independent deep copy that is still a Collider of the same class', function()
    local c = T.Collider(H.Rectangle(0, 0, 2), T.Collider(H.Circle(10, 0, 1)))
    local k = c:copy()
    assert.is_true(k:is(T.Collider))
    assert.equals(getmetatable(c), getmetatable(k))
    assert.are_not.equal((c:unpack()), (k:unpack()))
    assert.equals(k, select(2, k:unpack()):getParent())
    assert.equals(select(2, k:unpack()), (select(2, k:unpack()):unpack()):getParent())
    k:translate(100, 0)
    nearList({ c:getCentroid() }, { k:getCentroid() - 100, 0 })
    local cap = T.Capsule(0, 0, 10, 30, 0.5):copy(5, 5, 0)
    assert.is_true(cap:is(T.Capsule))
    nearList(bbox(cap), { 0, -10, 10, 30 })
  end)

  it('ipairs yields parent, shape and index', function()
    local inner = T.Collider(H.Circle(0, 0, 1), H.Circle(2, 0, 1))
    local c = T.Collider(H.Rectangle(0, 0, 1), inner)
    local got = {}
    for parent, shape, index in c:ipairs() do got[#got + 1] = { parent, shape, index } end
    local i1, i2 = inner:unpack()
    assert.same({ { c, (c:unpack()), 1 }, { inner, i1, 1 }, { inner, i2, 2 } }, got)
  end)

  it('containsPoint checks every member', function()
    local c = T.Collider(H.Rectangle(0, 0, 2), H.Circle(10, 0, 1))
    assert.is_true(c:containsPoint(10, 0.5))
    assert.is_false(c:containsPoint(5, 0))
  end)
end)

describe('Collider._of (strike\'s constructors: a collider from a list of new members)', function()
  -- every field and slot, the members' too, as a table of strings (the tables by what they are)
  local function state(c)
    local out = {}
    local function put(prefix, t)
      for k, v in pairs(t) do
        local s = type(v) == 'table' and (v == c and 'self' or v == c._shapes and 'shapes' or 'table') or tostring(v)
        out[#out + 1] = prefix .. tostring(k) .. '=' .. s
      end
    end
    put('', c)
    put('shapes.', c._shapes)
    for i, m in ipairs(c._shapes) do
      out[#out + 1] = ('member %d parent is self: %s'):format(i, tostring(m._parent == c))
    end
    table.sort(out)
    return table.concat(out, '\n')
  end
  local function members()
    return { H.Rectangle(0, 0, 4, 2), H.Circle(5, 1, 1), T.Collider(H.Point(9, 9)),
      T.Concave(0, 0, 4, 0, 4, 4, 2, 1, 0, 4) }
  end

  it('makes the collider Collider(...) makes from the same members', function()
    local a, b = T.Collider(unpack(members())), T.Collider._of(members())
    assert.equals(getmetatable(a), getmetatable(b))
    assert.equals(state(a), state(b))
    for _, c in ipairs({ a, b }) do c:getBounds(); c:getArea(); c:getShapeCount() end -- (and after the caches fill)
    assert.equals(state(a), state(b))
    nearList({ a:getBounds() }, { b:getBounds() })
    near(a:getArea(), b:getArea())
    assert.equals(a:getShapeCount(), b:getShapeCount())
  end)

  it('is how Chain and Concave hold their members: as Collider.new and add would', function()
    local cases = { { T.Chain(0, 0, 4, 0, 4, 3, 9, 3), 3, { 0, 0, 9, 3 } },
      { T.Chain({ 0, 0, 4, 0, 4, 3 }, true), 3, { 0, 0, 4, 3 } },
      { T.Concave(0, 0, 4, 0, 4, 4, 2, 1, 0, 4), 3, { 0, 0, 4, 4 } } }
    for _, case in ipairs(cases) do
      local c = case[1]
      assert.equals(case[2], select('#', c:unpack()))
      local ref = setmetatable(T.Collider._alloc(), getmetatable(c))
      T.Collider.new(ref)
      ref._loop = c._loop
      for _, m in ipairs({ c:unpack() }) do ref:add(m:copy()) end
      assert.equals(state(ref), state(c))
      nearList({ c:getBounds() }, case[3])
      nearList({ ref:getBounds() }, case[3])
    end
  end)

  it('takes the list as its children\'s: the members belong to it', function()
    local list = members()
    local c = T.Collider._of(list)
    assert.equals(list, c._shapes)
    assert.equals(4, select('#', c:unpack()))
    raisesAt(function() T.Collider(list[1]) end, 'strike.Collider:add: argument 1 already belongs to a collider')
    local s = S.pace()
    s:add(c)
    assert.equals(0, #s:queryPoint(6.6, 1))
    c:translate(1, 0) -- (a change reaches the space as for any collider)
    assert.equals(1, #s:queryPoint(6.6, 1))
  end)
end)

describe('Collider:consolidate', function()
  it('merges adjacent convex pieces whose union is convex', function()
    local c = T.Collider(H.Rectangle(0, 0, 10), H.Rectangle(10, 0, 10), H.Rectangle(20, 0, 10))
    assert.equals(c, c:consolidate())
    assert.equals(1, select('#', c:unpack()))
    assert.equals(4, (c:unpack()):getVertexCount())
    assert.equals(300, c:getArea())
    assert.equals(c, (c:unpack()):getParent())
  end)

  it('leaves pieces alone where the union would be concave, overlapping, or apart', function()
    local l = T.Collider(H.Rectangle(0, 0, 10), H.Rectangle(10, 0, 10), H.Rectangle(0, 10, 10))
    l:consolidate()
    assert.equals(2, select('#', l:unpack())) -- two squares merge, the L corner stays
    local o = T.Collider(H.Rectangle(0, 0, 10), H.Rectangle(5, 0, 10))
    assert.equals(2, select('#', o:consolidate():unpack()))
    local apart = T.Collider(H.Rectangle(0, 0, 10), H.Rectangle(11, 0, 10))
    assert.equals(2, select('#', apart:consolidate():unpack()))
  end)

  it('merges partial edges when the result is convex, and recurses', function()
    local tri = H.ConvexPolygon(0, 0, 10, 0, 0, 10)
    local tri2 = H.ConvexPolygon(10, 0, 10, 10, 0, 10)
    local c = T.Collider(T.Collider(tri, tri2), H.Circle(50, 0, 1), H.Edge(0, 20, 10, 20))
    c:consolidate()
    assert.equals(1, select('#', (c:unpack()):unpack()))
    assert.equals(100, (c:unpack()):getArea())
    assert.equals(3, c:getShapeCount())
  end)
end)

describe('Capsule', function()
  it('is dx wide and dy tall, caps included', function()
    local c = T.Capsule(0, 0, 10, 30)
    nearList(bbox(c), { -5, -15, 10, 30 })
    near(c:getArea(), 10 * 20 + pi * 25)
    nearList({ c:getCentroid() }, { 0, 0 })
    nearList({ c:getDimensions() }, { 10, 30 })
    near(c:getRadius(), 15)
  end)

  it('keeps its angle under rotateTo', function()
    local c = T.Capsule(0, 0, 10, 30, pi / 2)
    nearList(bbox(c), { -15, -5, 30, 10 })
    near(c:getAngle(), pi / 2)
    c:rotateTo(0)
    nearList(bbox(c), { -5, -15, 10, 30 })
    c:scale(2)
    near(c:getArea(), 4 * (10 * 20 + pi * 25))
  end)

  it('is one circle when dy == dx, and validates', function()
    assert.equals(1, select('#', T.Capsule(0, 0, 10, 10):unpack()))
    raisesAt(function() T.Capsule(0, 0, 10, 5) end, 'strike.Capsule: height (caps included) must be at least the width')
    raisesAt(function() T.Capsule(0, 0, 10) end, 'strike.Capsule: height must be a finite number > 0, got nil')
  end)
end)

describe('Concave', function()
  it('splits an L into two convex pieces with the right area', function()
    local l = T.Concave(0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20)
    assert.equals(2, select('#', l:unpack()))
    near(l:getArea(), 300)
    local cw = T.Concave({ 0, 20, 10, 20, 10, 10, 20, 10, 20, 0, 0, 0 })
    near(cw:getArea(), 300)
    assert.is_true(l:containsPoint(5, 15))
    assert.is_false(l:containsPoint(15, 15))
  end)

  it('collides like its outline', function()
    local u = T.Concave(0, 0, 30, 0, 30, 30, 20, 30, 20, 10, 10, 10, 10, 30, 0, 30)
    assert.is_false(S.triking(u, T.Circle(15, 25, 4)))
    assert.truthy(S.triking(u, T.Circle(15, 5, 4)))
  end)

  it('rejects self-intersecting and degenerate outlines', function()
    raisesAt(function() T.Concave(0, 0, 10, 10, 10, 0, 0, 10) end, 'strike.Concave: outline intersects itself')
    raisesAt(function() T.Concave(0, 0, 1, 1, 2, 2) end, 'strike.Concave:')
    raisesAt(function() T.Concave(0, 0, 1, 1) end, 'strike.Concave:')
    raisesAt(function() T.Concave(0, 0, 1, 1, 0 / 0, 1) end, 'strike.Concave: x3 must be a finite number, got nan')
    raisesAt(function() T.Concave(0, 0, 1) end, 'odd number of values (3)')
  end)
end)

describe('collider errors', function()
  it('containsPoint validates the point', function()
    raisesAt(function() T.Collider():containsPoint(nil, 1) end,
      'strike.Collider:containsPoint: point x must be a finite number, got nil')
  end)

  it('a single-shape collider whose shape was unregistered says so', function()
    local Tri = H.ConvexPolygon:extend()
    function Tri:new() Tri.super.new(self, 0, 0, 1, 0, 0, 1) end
    H.SpecGoneTri = Tri
    assert.is_table(T.SpecGoneTri())
    H.SpecGoneTri = nil
    raisesAt(function() T.SpecGoneTri() end, 'strike.trikers.SpecGoneTri: S.hapes.SpecGoneTri is no longer registered')
  end)

  it('a file that returns something other than a class is an error at the line that named it', function()
    package.preload['strike.shapes.SpecWeird'] = function() return 42 end
    package.preload['strike.colliders.SpecWeirder'] = function() return H.Circle end
    finally(function()
      package.preload['strike.shapes.SpecWeird'], package.preload['strike.colliders.SpecWeirder'] = nil, nil
      package.loaded['strike.shapes.SpecWeird'], package.loaded['strike.colliders.SpecWeirder'] = nil, nil
    end)
    raisesAt(function() local _ = H.SpecWeird end,
      'strike: shapes/SpecWeird.lua must return a class extending a strike shape')
    raisesAt(function() local _ = T.SpecWeirder end, 'strike: colliders/SpecWeirder.lua must return a class extending')
  end)

  it('a file that fails to load reports its own error', function()
    package.preload['strike.shapes.SpecBroken'] = function() error('boom in the file') end
    finally(function() package.preload['strike.shapes.SpecBroken'] = nil end)
    local ok, err = pcall(function() return H.SpecBroken end)
    assert.is_false(ok)
    assert.matches('boom in the file', err)
  end)
end)

describe('more collider queries', function()
  it('getBounds gives the min and max corners; Capsule:getAreaCentroid the true area', function()
    local c = T.Collider(H.Rectangle(0, 0, 2), H.Circle(10, 0, 1))
    nearList({ c:getBounds() }, { -1, -1, 11, 1 })
    local a, x, y = T.Capsule(3, 4, 10, 30):getAreaCentroid()
    nearList({ a, x, y }, { 200 + 25 * pi, 3, 4 })
  end)
end)
