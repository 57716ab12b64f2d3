-- A method called with '.' instead of ':' (`k.add(b)` for `k:add(b)`) gets a wrong `self`.
-- Every public method checks its `self` first and raises, at the caller's line, an error
-- that names the method and says to call it with ':', before it touches anything.
local S = require('strike')
local expect = require('spec.helpers.expect')
local raisesAt = expect.raisesAt

local Object = require('strike.class')
local Shape = require('strike.base.Shape')
local VertexShape = require('strike.base.VertexShape')
local ChainSegment = require('strike.base.ChainSegment')
local MTV = require('strike.collide.MTV')
local Space = require('strike.space.Space')
local H, T = S.hapes, S.trikers

local CALL = "call it with ':'"

-- Every public method (a function-valued key not starting with `_`) of every public class,
-- written out, with the name its errors use (the class that documents it: all shapes share
-- strike.Shape's methods, all colliders strike.Collider's). `self` says what a method must
-- be called on: 'shape', 'collider', 'mtv', 'new' (a constructor body: an instance under
-- construction), 'class' (extend) or 'any' (is). The walk below fails when a class has a
-- public function missing here.
local METHODS = {
  { 'Object', Object, {
    new = { 'new', 'strike.Object:new' },
    extend = { 'class', 'strike.Object:extend' },
    is = { 'any', 'strike.Object:is' },
  } },
  { 'Shape', Shape, {
    translate = { 'shape', 'strike.Shape:translate' },
    translateTo = { 'shape', 'strike.Shape:translateTo' },
    rotate = { 'shape', 'strike.Shape:rotate' },
    rotateTo = { 'shape', 'strike.Shape:rotateTo' },
    scale = { 'shape', 'strike.Shape:scale' },
    getAngle = { 'shape', 'strike.Shape:getAngle' },
    getScale = { 'shape', 'strike.Shape:getScale' },
    getCentroid = { 'shape', 'strike.Shape:getCentroid' },
    getArea = { 'shape', 'strike.Shape:getArea' },
    getAreaCentroid = { 'shape', 'strike.Shape:getAreaCentroid' },
    getRadius = { 'shape', 'strike.Shape:getRadius' },
    getBbox = { 'shape', 'strike.Shape:getBbox' },
    getBounds = { 'shape', 'strike.Shape:getBounds' },
    getRoot = { 'shape', 'strike.Shape:getRoot' },
    getParent = { 'shape', 'strike.Shape:getParent' },
    getKind = { 'shape', 'strike.Shape:getKind' },
    copy = { 'shape', 'strike.Shape:copy' },
    draw = { 'shape', 'strike.Shape:draw' },
    rayIntersections = { 'shape', 'strike.Shape:rayIntersections' },
    rayIntersects = { 'shape', 'strike.Shape:rayIntersects' },
    rayCast = { 'shape', 'strike.Shape:rayCast' },
    segmentCast = { 'shape', 'strike.Shape:segmentCast' },
  } },
  { 'VertexShape', VertexShape, {
    getVertexCount = { 'shape', 'strike.Shape:getVertexCount' },
    getVertex = { 'shape', 'strike.Shape:getVertex' },
    getEdge = { 'shape', 'strike.Shape:getEdge' },
    getNormal = { 'shape', 'strike.Shape:getNormal' },
    getVertices = { 'shape', 'strike.Shape:getVertices' },
    project = { 'shape', 'strike.Shape:project' },
    getSupport = { 'shape', 'strike.Shape:getSupport' },
    containsPoint = { 'shape', 'strike.Shape:containsPoint' },
    ipairs = { 'shape', 'strike.Shape:ipairs' },
    vecs = { 'shape', 'strike.Shape:vecs' },
    getRounding = { 'shape', 'strike.Shape:getRounding' },
  } },
  { 'Circle', H.Circle, {
    new = { 'new', 'strike.Circle:new' },
    getRadius = { 'shape', 'strike.Shape:getRadius' },
    getRounding = { 'shape', 'strike.Shape:getRounding' },
    project = { 'shape', 'strike.Shape:project' },
    containsPoint = { 'shape', 'strike.Shape:containsPoint' },
    getVertex = { 'shape', 'strike.Shape:getVertex' },
    getEdge = { 'shape', 'strike.Shape:getEdge' },
    getVertexCount = { 'shape', 'strike.Shape:getVertexCount' },
    getVertices = { 'shape', 'strike.Shape:getVertices' },
    getSupport = { 'shape', 'strike.Shape:getSupport' },
    ipairs = { 'shape', 'strike.Shape:ipairs' },
    vecs = { 'shape', 'strike.Shape:vecs' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'ConvexPolygon', H.ConvexPolygon, {
    new = { 'new', 'strike.ConvexPolygon:new' },
    merge = { 'shape', 'strike.ConvexPolygon:merge' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'Capsule', H.Capsule, {
    new = { 'new', 'strike.Capsule:new' },
    getDimensions = { 'shape', 'strike.Capsule:getDimensions' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'Edge', H.Edge, {
    new = { 'new', 'strike.Edge:new' },
    getLength = { 'shape', 'strike.Edge:getLength' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'Ellipse', H.Ellipse, {
    new = { 'new', 'strike.Ellipse:new' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'Point', H.Point, {
    new = { 'new', 'strike.Point:new' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'Rectangle', H.Rectangle, {
    new = { 'new', 'strike.Rectangle:new' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'RegularPolygon', H.RegularPolygon, {
    new = { 'new', 'strike.RegularPolygon:new' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'ChainSegment', ChainSegment, {
    new = { 'new', 'strike.ChainSegment:new' },
    getGhostVertices = { 'shape', 'strike.ChainSegment:getGhostVertices' },
    isConvex = { 'shape', 'strike.ChainSegment:isConvex' },
    unpack = { 'shape', 'strike.Shape:unpack' },
  } },
  { 'Collider', T.Collider, {
    new = { 'new', 'strike.Collider:new' },
    add = { 'collider', 'strike.Collider:add' },
    remove = { 'collider', 'strike.Collider:remove' },
    unpack = { 'collider', 'strike.Collider:unpack' },
    calcAreaCentroid = { 'collider', 'strike.Collider:calcAreaCentroid' },
    calcRadius = { 'collider', 'strike.Collider:calcRadius' },
    getArea = { 'collider', 'strike.Collider:getArea' },
    getCentroid = { 'collider', 'strike.Collider:getCentroid' },
    getAreaCentroid = { 'collider', 'strike.Collider:getAreaCentroid' },
    getRadius = { 'collider', 'strike.Collider:getRadius' },
    getBbox = { 'collider', 'strike.Collider:getBbox' },
    getBounds = { 'collider', 'strike.Collider:getBounds' },
    getAngle = { 'collider', 'strike.Collider:getAngle' },
    getShapeCount = { 'collider', 'strike.Collider:getShapeCount' },
    getRoot = { 'collider', 'strike.Collider:getRoot' },
    getParent = { 'collider', 'strike.Collider:getParent' },
    elems = { 'collider', 'strike.Collider:elems' },
    ipairs = { 'collider', 'strike.Collider:ipairs' },
    project = { 'collider', 'strike.Collider:project' },
    containsPoint = { 'collider', 'strike.Collider:containsPoint' },
    translate = { 'collider', 'strike.Collider:translate' },
    translateTo = { 'collider', 'strike.Collider:translateTo' },
    rotate = { 'collider', 'strike.Collider:rotate' },
    rotateTo = { 'collider', 'strike.Collider:rotateTo' },
    scale = { 'collider', 'strike.Collider:scale' },
    copy = { 'collider', 'strike.Collider:copy' },
    draw = { 'collider', 'strike.Collider:draw' },
    consolidate = { 'collider', 'strike.Collider:consolidate' },
    rayIntersections = { 'collider', 'strike.Collider:rayIntersections' },
    rayIntersects = { 'collider', 'strike.Collider:rayIntersects' },
    rayCast = { 'collider', 'strike.Collider:rayCast' },
    segmentCast = { 'collider', 'strike.Collider:segmentCast' },
  } },
  { 'Capsule', T.Capsule, {
    new = { 'new', 'strike.Capsule:new' },
    getDimensions = { 'collider', 'strike.Capsule:getDimensions' },
  } },
  { 'Chain', T.Chain, {
    new = { 'new', 'strike.Chain:new' },
    isLoop = { 'collider', 'strike.Chain:isLoop' },
  } },
  { 'Concave', T.Concave, {
    new = { 'new', 'strike.Concave:new' },
  } },
  -- single.lua makes one class per shape name, each with its own constructor
  { 'trikers.Rectangle', T.Rectangle, {
    new = { 'new', 'strike.trikers.Rectangle:new' },
  } },
  { 'trikers.Circle', T.Circle, {
    new = { 'new', 'strike.trikers.Circle:new' },
  } },
  { 'MTV', MTV, {
    new = { 'new', 'strike.MTV:new' },
    mag = { 'mtv', 'strike.MTV:mag' },
    mag2 = { 'mtv', 'strike.MTV:mag2' },
    scale = { 'mtv', 'strike.MTV:scale' },
    setCollider = { 'mtv', 'strike.MTV:setCollider' },
    setCollided = { 'mtv', 'strike.MTV:setCollided' },
    setColliderShape = { 'mtv', 'strike.MTV:setColliderShape' },
    setCollidedShape = { 'mtv', 'strike.MTV:setCollidedShape' },
    setEdgeIndex = { 'mtv', 'strike.MTV:setEdgeIndex' },
    setSeparating = { 'mtv', 'strike.MTV:setSeparating' },
    set = { 'mtv', 'strike.MTV:set' },
  } },
  { 'Space', Space, {
    new = { 'new', 'strike.Space:new' },
    add = { 'space', 'strike.Space:add' },
    set = { 'space', 'strike.Space:set' },
    get = { 'space', 'strike.Space:get' },
    remove = { 'space', 'strike.Space:remove' },
    has = { 'space', 'strike.Space:has' },
    count = { 'space', 'strike.Space:count' },
    bodies = { 'space', 'strike.Space:bodies' },
    setFilter = { 'space', 'strike.Space:setFilter' },
    on = { 'space', 'strike.Space:on' },
    off = { 'space', 'strike.Space:off' },
    collisions = { 'space', 'strike.Space:collisions' },
    check = { 'space', 'strike.Space:check' },
    queryPoint = { 'space', 'strike.Space:queryPoint' },
    queryRect = { 'space', 'strike.Space:queryRect' },
    queryShape = { 'space', 'strike.Space:queryShape' },
    rayCast = { 'space', 'strike.Space:rayCast' },
    rayCastAll = { 'space', 'strike.Space:rayCastAll' },
    cast = { 'space', 'strike.Space:cast' },
    move = { 'space', 'strike.Space:move' },
    addResponse = { 'space', 'strike.Space:addResponse' },
  } },
}

-- Public functions that are no methods, so have no `self` to check.
local NOT_METHODS = {
  ['Shape.checkClass'] = 'takes the class to check as its first argument',
}

local function sortedKeys(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  table.sort(keys, function(a, b) return tostring(a) < tostring(b) end)
  return keys
end

-- Wrong selves, each with how the error describes it, by what the method needs.
local function wrongSelves(need)
  local shape, collider, mtv = H.Rectangle(0, 0, 2), T.Circle(0, 0, 1), S.MTV(1, 0)
  local list = { { nil, 'nil' }, { 7, 'the number 7' } }
  local function add(v, desc) list[#list + 1] = { v, desc } end
  if need == 'shape' then
    add(collider, 'a collider')
    add(mtv, 'an MTV')
  elseif need == 'collider' then
    add(shape, 'a shape')
    add(mtv, 'an MTV')
  elseif need == 'mtv' then
    add(shape, 'a shape')
    add(collider, 'a collider')
  elseif need == 'class' then
    add(shape, 'a shape')
    add(collider, 'a collider')
  elseif need == 'space' then
    add(shape, 'a shape')
    add(collider, 'a collider')
    add(mtv, 'an MTV')
  elseif need == 'new' then
    add({}, 'a table that is no strike object')
  end
  return list
end

describe("a method called with '.' instead of ':'", function()
  it('lists every public function of every public class (walking each class in sorted order)', function()
    local covered = 0
    for _, entry in ipairs(METHODS) do
      local label, cls, methods = entry[1], entry[2], entry[3]
      assert.is_table(cls, label)
      for _, k in ipairs(sortedKeys(cls)) do
        local v = rawget(cls, k)
        if type(k) == 'string' and k:sub(1, 1) ~= '_' and type(v) == 'function' then
          local name = label .. '.' .. k
          assert(methods[k] or NOT_METHODS[name],
            ('%s is a public function with no entry in spec/self_spec.lua METHODS'):format(name))
        end
      end
      for _, k in ipairs(sortedKeys(methods)) do
        assert.is_function(rawget(cls, k), label .. '.' .. k .. ' is listed but not defined there')
        covered = covered + 1
      end
    end
    assert.is_true(covered > 100, 'methods covered: ' .. covered)
  end)

  for _, entry in ipairs(METHODS) do
    local label, cls, methods = entry[1], entry[2], entry[3]
    for _, k in ipairs(sortedKeys(methods)) do
      local need, fname = methods[k][1], methods[k][2]
      it(('%s:%s checks its self'):format(label, k), function()
        local fn = rawget(cls, k)
        for _, case in ipairs(wrongSelves(need)) do
          local bad, desc = case[1], case[2]
          raisesAt(function() fn(bad) end, ("%s: called with '.' instead of ':' (self is %s); %s"):format(fname,
            desc, CALL))
        end
      end)
    end
  end

  it("Object:is: obj.is(Class) (the class as self, nothing as the class to test)", function()
    local c = T.Circle(0, 0, 1)
    raisesAt(function() c.is(T.Collider) end, "strike.Object:is: called with '.' instead of ':' (self is a class)")
    assert.is_true(c:is(T.Collider))
    assert.is_false(c:is(H.Circle))
    assert.is_false(c:is(nil)) -- (a class that is not there: no error, as before)
  end)

  it("Object:extend names what to call it on", function()
    raisesAt(function() Object.extend(H.Rectangle(0, 0, 1)) end, "self is a shape); call it with ':' on a class")
  end)

  it('k.add(b) raises and leaves both unchanged; k:add(b) then finds the real overlap', function()
    local k = T.Collider()
    local b = H.Rectangle(0, 0, 10)
    raisesAt(function() k.add(b) end, "strike.Collider:add: called with '.' instead of ':' (self is a shape)")
    assert.equals(0, select('#', k:unpack()))
    assert.equals(0, k:getShapeCount())
    assert.is_nil(rawget(b, 'shapes'))
    assert.is_nil(b:getParent())
    k:add(b)
    assert.equals(1, k:getShapeCount())
    assert.equals(k, b:getParent())
    local m = S.triking(k, T.Circle(6, 0, 2))
    assert.is_table(m)
    expect.near(m.depth, 1)
  end)

  it('c.remove(1), c.elems() and s.getCentroid() raise at the caller', function()
    local c = T.Collider(H.Circle(0, 0, 1), H.Circle(5, 0, 1))
    local s = (c:unpack())
    raisesAt(function() c.remove(1) end,
      "strike.Collider:remove: called with '.' instead of ':' (self is the number 1)")
    assert.equals(2, c:getShapeCount())
    raisesAt(function() c.elems() end, "strike.Collider:elems: called with '.' instead of ':' (self is nil)")
    raisesAt(function() s.getCentroid() end, "strike.Shape:getCentroid: called with '.' instead of ':' (self is nil)")
    raisesAt(function() c.translate(5, 0) end, "strike.Collider:translate: called with '.' instead of ':'")
    raisesAt(function() s.translate(5, 0) end, "strike.Shape:translate: called with '.' instead of ':'")
    raisesAt(function() c.add('x') end,
      [[strike.Collider:add: called with '.' instead of ':' (self is the string "x")]])
    raisesAt(function() s.rotate(true) end, "strike.Shape:rotate: called with '.' instead of ':' (self is true)")
    raisesAt(function() s.scale(print) end,
      "strike.Shape:scale: called with '.' instead of ':' (self is a function)")
    expect.nearList({ c:getCentroid() }, { 2.5, 0 })
    assert.equals(2, select('#', c:unpack()))
  end)

  it('works for subclasses, whose errors are raised at the caller too', function()
    local Trapezoid = H.ConvexPolygon:extend()
    function Trapezoid:new(x, y) Trapezoid.super.new(self, x, y, x + 4, y, x + 3, y + 1, x + 1, y + 1) end
    local t = Trapezoid(0, 0)
    raisesAt(function() t.getBbox() end, "strike.Shape:getBbox: called with '.' instead of ':' (self is nil)")
    raisesAt(function() Trapezoid.super.new(0, 0) end, "strike.ConvexPolygon:new: called with '.' instead of ':'")
    expect.nearList({ t:getBbox() }, { 0, 0, 4, 1 })
  end)

  it("still accepts the selves strike itself passes", function()
    -- a collider whose constructor makes no list of children before its first add
    -- (docs/extending.md)
    local Bare = T.Collider:extend()
    function Bare:new(x) self:add(H.Circle(x, 0, 1)) end
    local bare = Bare(3)
    assert.equals(1, bare:getShapeCount())
    assert.equals(bare, bare:getRoot())
    -- S.triking fills a plain `out` table
    local out = {}
    assert.equals(out, S.triking(T.Circle(0, 0, 2), T.Circle(3, 0, 2), out))
    expect.near(out.depth, 1)
    -- shapes and colliders share getRoot's answer
    local inner = T.Collider(H.Circle(0, 0, 1))
    local outer = T.Collider(inner)
    assert.equals(outer, (inner:unpack()):getRoot())
    assert.equals(outer, inner:getRoot())
  end)
end)
