-- Regression specs: one describe per bug fixed in the library, named after the bug. Each
-- failed on the code before its fix (commit fc4175e) and passes now; the hostile-input
-- list of bug 8 is pinned case by case.
local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local H, T = S.hapes, S.trikers

-- Every leaf's world vertices (or centre and radius), flattened: a snapshot of the geometry.
local function geometry(body)
  local out = {}
  local function leaf(s)
    if s:getKind() == 'circle' then
      local x, y = s:getCentroid()
      out[#out + 1], out[#out + 2], out[#out + 3] = x, y, s:getRadius()
    else
      local v = s:getVertices()
      for i = 1, #v do out[#out + 1] = v[i] end
    end
  end
  if body.type == 'collider' then
    for s in body:elems() do leaf(s) end
  else
    leaf(body)
  end
  return out
end

-- How many colliders (among `colliders`) hold `child` directly.
local function holders(child, colliders)
  local n = 0
  for _, c in ipairs(colliders) do
    for _, k in ipairs({ c:unpack() }) do
      if k == child then n = n + 1 end
    end
  end
  return n
end

describe('bug 1: the same shape twice in one add was counted twice and could join a second collider', function()
  it('rejects a shape given twice in one call, at the caller\'s line, and leaves it free', function()
    local s = H.Rectangle(0, 0, 10, 10)
    raisesAt(function() T.Collider(s, s) end, 'strike.Collider:add: argument 2 is argument 1 again')
    assert.is_nil(s:getParent())
    local c = T.Collider(s)
    assert.equals(100, c:getArea()) -- once, not 200
    assert.equals(1, c:getShapeCount())
  end)

  it('rejects a shape already held, by the same collider or another, even after a remove', function()
    local s, t = H.Circle(0, 0, 5), H.Circle(20, 0, 5)
    local c = T.Collider(s, t)
    raisesAt(function() c:add(s) end, 'strike.Collider:add: argument 1 already belongs to a collider')
    raisesAt(function() T.Collider(t) end, 'strike.Collider:add: argument 1 already belongs to a collider')
    assert.equals(s, c:remove(1))
    local d = T.Collider(s) -- free after the remove: it may join another collider, once
    assert.equals(1, holders(s, { c, d }))
    assert.equals(d, s:getParent())
    assert.equals(1, c:getShapeCount())
    near(c:getArea(), 25 * math.pi)
  end)

  it('holds a shape once after a double add and a remove (it used to join a second collider)', function()
    local s = H.Rectangle(0, 0, 10, 10)
    assert.is_false(pcall(T.Collider, s, s))
    local c = T.Collider(s)
    c:remove(1)
    local d = T.Collider(s)
    assert.equals(1, holders(s, { c, d }))
    assert.equals(0, c:getShapeCount())
    assert.equals(100, d:getArea())
  end)

  it('rejects a collider given twice, or one already nested elsewhere', function()
    local inner = T.Collider(H.Rectangle(0, 0, 2, 2))
    raisesAt(function() T.Collider(inner, inner) end, 'strike.Collider:add: argument 2 is argument 1 again')
    local outer = T.Collider(inner)
    raisesAt(function() T.Collider(inner) end, 'strike.Collider:add: argument 1 already belongs to a collider')
    raisesAt(function() T.Collider((outer:unpack()):unpack()) end, 'argument 1 already belongs to a collider')
    raisesAt(function() T.Collider(H.Circle(0, 0, 1), outer, outer) end, 'argument 3 is argument 2 again')
    assert.equals(4, outer:getArea())
  end)

  it('adds nothing when any argument is rejected', function()
    local a, b = H.Circle(0, 0, 1), H.Circle(5, 0, 1)
    local c = T.Collider()
    assert.has_error(function() c:add(a, b, a) end)
    assert.equals(0, c:getShapeCount())
    assert.is_nil(a:getParent())
    assert.is_nil(b:getParent())
  end)
end)

describe('bug 3: copy deep-copied user fields (a cyclic table overflowed, the entity was a copy)', function()
  local function cyclic()
    local p = { name = 'player' }
    p.world = { p = p }
    return p
  end

  it('shares a shape\'s user fields, cyclic ones included, by reference', function()
    local box = H.Rectangle(0, 0, 10, 10)
    local p = cyclic()
    box.entity = p
    local k = box:copy()
    assert.equals(box.entity, k.entity)
    assert.equals(p, k.entity.world.p)
  end)

  it('shares the user fields of a collider and of its members', function()
    local p = cyclic()
    local member = H.Circle(0, 0, 5)
    member.entity = p
    local c = T.Collider(T.Collider(member), H.Rectangle(20, 0, 4, 4))
    c.entity = p
    local k = c:copy()
    assert.equals(p, k.entity)
    assert.equals(p, (k:unpack()):unpack().entity)
    assert.are_not.equal(member, (k:unpack()):unpack())
  end)

  -- Each body, a way to move it, and its copy: moving either leaves the other as it was.
  local bodies = {
    { 'a Rectangle', function() return H.Rectangle(0, 0, 10, 4, 0.3) end },
    { 'a Circle', function() return H.Circle(0, 0, 5) end },
    { 'an Edge', function() return H.Edge(0, 0, 10, 5) end },
    { 'an Ellipse', function() return H.Ellipse(0, 0, 8, 4) end },
    { 'a nested collider', function()
      return T.Collider(T.Collider(H.Rectangle(0, 0, 4, 4), H.Circle(10, 0, 2)), H.Edge(0, 10, 5, 10))
    end },
    { 'a Chain', function() return T.Chain(0, 0, 10, 0, 20, 5, 30, 5) end },
    { 'a Concave', function() return T.Concave(0, 0, 30, 0, 30, 30, 20, 30, 20, 10, 0, 10) end },
    { 'a Capsule', function() return T.Capsule(0, 0, 10, 30, 0.5) end },
  }
  for _, case in ipairs(bodies) do
    it('gives ' .. case[1] .. ' a copy that moves independently', function()
      local body = case[2]()
      local before = geometry(body)
      local k = body:copy()
      nearList(geometry(k), before, 1e-9)
      k:translate(7, -3):rotate(0.8):scale(1.5)
      nearList(geometry(body), before, 0) -- the original has not moved
      local moved = geometry(k)
      body:translate(-50, 50)
      nearList(geometry(k), moved, 0) -- nor the copy, when the original moves
      assert.equals(getmetatable(body), getmetatable(k))
    end)
  end

  it('gives a copy that belongs to no collider and can join one', function()
    local s = H.Rectangle(0, 0, 2, 2)
    local inner = T.Collider(s)
    local outer = T.Collider(inner)
    local ks, ki = s:copy(), inner:copy()
    assert.is_nil(ks:getParent())
    assert.is_nil(ki:getParent())
    assert.equals(ki, (ki:unpack()):getParent())
    assert.are_not.equal(s, (ki:unpack()))
    local other = T.Collider(ks, ki) -- neither is held anywhere
    assert.equals(2, other:getShapeCount())
    assert.equals(1, outer:getShapeCount())
    assert.truthy(S.triking(outer, other)) -- separate roots: the copies collide with the originals
  end)
end)

describe('bug 4: S.ite on a stale MTV gave contacts for shapes that had moved apart', function()
  -- Contacts as comparable lists: { nx, ny, count, {x, y, depth, id}... }.
  local function flat(c)
    if not c then return nil end
    local out = { c.nx, c.ny, c.count }
    for i = 1, c.count do
      local p = c[i]
      out[#out + 1] = { p.x, p.y, p.depth, p.id }
    end
    return out
  end
  local function same(got, want)
    assert.is_table(got)
    assert.is_table(want)
    assert.equals(want[3], got[3])
    near(got[1], want[1], 1e-12)
    near(got[2], want[2], 1e-12)
    for i = 4, #want do
      nearList({ got[i][1], got[i][2], got[i][3] }, { want[i][1], want[i][2], want[i][3] }, 1e-9)
      assert.equals(want[i][4], got[i][4])
    end
  end
  -- What a fresh test says about the MTV's pair now.
  local function fresh(m) return flat(S.ite(S.AT(m.colliderShape, m.collidedShape))) end

  it('returns nil once the shapes have moved apart', function()
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(8, 1, 10, 10)
    local m = S.AT(a, b)
    assert.is_table(S.ite(m))
    b:translate(100, 0)
    assert.is_nil(S.ite(m))
    assert.is_false(m.separating) -- the MTV itself is left as it was
    near(m.depth, 2)
  end)

  it('describes the shapes as they are when they moved but still overlap', function()
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(8, 1, 10, 10)
    local m = S.AT(a, b)
    b:translate(-5, 6) -- now the y axis is the shallower one
    same(flat(S.ite(m)), fresh(m))
    b:rotate(0.4)
    same(flat(S.ite(m)), fresh(m))
    a:scale(1.3)
    same(flat(S.ite(m)), fresh(m))
    near(S.ite(m).ny, fresh(m)[2])
  end)

  it('re-tests polygon-circle and circle-circle pairs too', function()
    local box, c1, c2 = H.Rectangle(0, 0, 10, 10), H.Circle(7, 0, 3), H.Circle(12, 0, 4)
    local m1, m2 = S.AT(box, c1), S.AT(c1, c2)
    c1:translate(0, 4)
    same(flat(S.ite(m1)), fresh(m1))
    same(flat(S.ite(m2)), fresh(m2))
    c1:translate(50, 0)
    assert.is_nil(S.ite(m1))
    assert.is_nil(S.ite(m2))
  end)

  it('notices a shape moved through its collider', function()
    local ca, cb = T.Rectangle(0, 0, 10, 10), T.Collider(H.Circle(40, 0, 2), H.Rectangle(9, 0, 10, 10))
    local m = S.triking(ca, cb)
    assert.truthy(m)
    cb:translate(0, 3)
    same(flat(S.ite(m)), fresh(m))
    cb:rotate(0.3, 0, 0)
    same(flat(S.ite(m)), fresh(m))
    cb:translate(100, 0)
    assert.is_nil(S.ite(m))
  end)

  it('works for an MTV from S.triking on nested colliders moved by the outer one', function()
    local inner = T.Collider(H.Rectangle(0, 0, 10, 10))
    local outer = T.Collider(inner, H.Circle(-50, 0, 1))
    local wall = T.Collider(T.Collider(H.Rectangle(9, 2, 10, 10)))
    local m = S.triking(outer, wall)
    assert.truthy(m)
    outer:translate(0.5, -1)
    same(flat(S.ite(m)), fresh(m))
    wall:scale(1.2)
    same(flat(S.ite(m)), fresh(m))
    outer:translate(-100, 0)
    assert.is_nil(S.ite(m))
  end)

  it('still gives a hand-made MTV\'s contacts along its own vector', function()
    -- The SAT would push along x (depth 2); the MTV made by hand says y.
    local a, b = H.Rectangle(0, 0, 10, 10), H.Rectangle(8, 1, 10, 10)
    local c = S.ite(S.MTV(0, 9, a, b))
    assert.is_table(c)
    near(c.nx, 0)
    near(c.ny, 1)
    assert.equals(2, c.count)
    local sat = S.ite(S.AT(a, b))
    near(sat.nx, 1)
  end)
end)

describe('the shape interface check: an incomplete shape class failed deep inside the narrow phase', function()
  local Shape = H.Circle.super

  it('reaches the base class', function()
    assert.equals('Shape', Shape.name)
    assert.equals(Shape, H.ConvexPolygon.super.super)
  end)

  it('rejects a bare Shape:extend() at registration, naming the missing member', function()
    local Bare = Shape:extend()
    raisesAt(function() H.Bare = Bare end, 'strike: S.hapes.Bare lacks `kind`, which every shape class must provide')
    local Kinded = Shape:extend()
    Kinded.kind = 'polygon'
    raisesAt(function() H.Kinded = Kinded end, 'S.hapes.Kinded lacks `_refresh`')
    assert.is_nil(rawget(H, 'Bare'))
    assert.is_nil(rawget(H, 'Kinded'))
  end)

  it('rejects an incomplete class registered by a file in shapes/', function()
    local mod = 'strike.shapes.BareFile'
    package.preload[mod] = function() return Shape:extend() end
    local ok, err = pcall(function() return H.BareFile end)
    package.preload[mod], package.loaded[mod] = nil, nil
    assert.is_false(ok)
    assert.truthy(tostring(err):find('the class in shapes/BareFile.lua lacks `kind`', 1, true), err)
  end)

  it('rejects an instance of an incomplete class at add and in S.AT and S.triking, naming the member', function()
    local Bare = Shape:extend() -- (its constructor is Object's empty one)
    local box = H.Rectangle(0, 0, 10, 10)
    raisesAt(function() T.Collider(Bare()) end, 'strike.Collider:add: argument 1 (a Shape) lacks `kind`')
    raisesAt(function() S.AT(box, Bare()) end, 'strike.AT: argument 2 (a Shape) lacks `kind`')
    raisesAt(function() S.AT(Bare(), box) end, 'strike.AT: argument 1 (a Shape) lacks `kind`')
    raisesAt(function() S.triking(Bare(), box) end, 'strike.triking: argument 1 (a Shape) lacks `kind`')
    local Kinded = Shape:extend()
    Kinded.kind = 'polygon'
    function Kinded:new(x, y) self:_setPose(x, y) end
    local ok, err = pcall(Kinded, 0, 0) -- (raised at the line of Kinded:new, the first outside strike)
    assert.is_false(ok)
    assert.truthy(tostring(err):find('strike.Shape: its class lacks `_refresh`', 1, true), err)
    local at = debug.getinfo(Kinded.new, 'S')
    assert.equals(at.short_src .. ':' .. at.linedefined .. ':', tostring(err):match('^[^:]*:%d+:'))
    raisesAt(function() S.AT(box, setmetatable({}, Kinded)) end, 'strike.AT: argument 2 (a Shape) lacks `_refresh`')
  end)

  it('rejects an instance of a complete class whose constructor never built it', function()
    local Hollow = H.ConvexPolygon:extend()
    function Hollow:new() end -- forgets Hollow.super.new(self, ...)
    raisesAt(function() S.AT(H.Circle(0, 0, 1), Hollow()) end, 'argument 2 (a ConvexPolygon) was not built')
    raisesAt(function() T.Collider(Hollow()) end, 'strike.Collider:add: argument 1 (a ConvexPolygon) was not built')
    local Empty = T.Collider:extend()
    function Empty:new() end -- forgets Empty.super.new(self)
    raisesAt(function() T.Collider(Empty()) end, 'strike.Collider:add: argument 1 (a Collider) was not built')
    raisesAt(function() S.triking(Empty(), H.Circle(0, 0, 1)) end, 'strike.triking: argument 1 (a Collider) was not')
  end)
end)

describe('bug 8: fake or wrong arguments failed deep inside instead of naming what was expected', function()
  local box = H.Rectangle(0, 0, 10, 10)
  local other = H.Rectangle(8, 0, 10, 10)
  local col = T.Rectangle(0, 0, 10, 10)
  local m = S.AT(box, other)

  it('S.triking and S.AT reject fake shapes, naming the function, the argument and what came', function()
    raisesAt(function() S.triking(box, { kind = 'circle' }) end,
      'strike.triking: argument 2 must be a strike collider or shape, got table')
    raisesAt(function() S.triking({ type = 'collider' }, box) end, 'strike.triking: argument 1 must be a strike')
    raisesAt(function() S.AT(box, { kind = 'polygon' }) end, 'strike.AT: argument 2 must be a strike shape, got table')
    raisesAt(function() S.AT({ type = 'shape', kind = 'polygon' }, box) end,
      'strike.AT: argument 1 must be a strike shape')
    raisesAt(function() S.AT(box, col) end, 'strike.AT: argument 2 must be a shape, got a collider')
    raisesAt(function() S.AT(box, 'box') end, 'strike.AT: argument 2 must be a strike shape, got string "box"')
    raisesAt(function() S.AT(S.MTV(), box) end, 'strike.AT: argument 1 must be a strike shape, got table')
    raisesAt(function() S.triking(nil, box) end,
      'strike.triking: argument 1 must be a strike collider or shape, got nil')
  end)

  it('S.triking and S.AT refuse a collider, a shape or a string as out (a collider was filled silently)', function()
    raisesAt(function() S.triking(box, other, col) end, 'strike.triking: argument 3 (out) must be a table such as'
      .. ' S.MTV(), got a collider')
    raisesAt(function() S.AT(box, other, H.Circle(0, 0, 1)) end, 'strike.AT: argument 3 (out) must be a table such as'
      .. ' S.MTV(), got a shape')
    raisesAt(function() S.AT(box, other, 'out') end, 'strike.AT: argument 3 (out) must be a table such as S.MTV()')
    assert.equals(1, col:getShapeCount())
  end)

  it('S.ite rejects fake MTVs, broken edge indices and strike objects as out', function()
    raisesAt(function() S.ite({ x = 1, y = 2 }) end,
      'strike.ite: the MTV must come from S.AT or S.triking (its colliderShape is nil, not a strike shape)')
    raisesAt(function() S.ite({ x = 1, y = 2, colliderShape = box, collidedShape = { kind = 'polygon' } }) end,
      'strike.ite: the MTV must come from S.AT or S.triking (its collidedShape is table, not a strike shape)')
    raisesAt(function() S.ite(S.MTV(1, 0, box, col)) end, 'its collidedShape is a collider, not a strike shape')
    raisesAt(function() S.ite(box) end, 'strike.ite: argument 1 must be an MTV, got a shape')
    raisesAt(function() S.ite(m, box) end, 'strike.ite: argument 2 (out) must be a table for the contacts')
    raisesAt(function() S.ite(m, col) end, 'for the contacts (a previous result, or {}), got a collider')
    raisesAt(function() S.ite(m, S.MTV()) end, 'for the contacts (a previous result, or {}), got an MTV')
    raisesAt(function() S.ite(m, 'out') end, 'got string "out"')
    local broken = S.AT(box, other):setEdgeIndex(99)
    raisesAt(function() S.ite(broken) end, 'strike.ite: the MTV\'s edgeIndex must be 0, i for face i of colliderShape'
      .. ' (it has 4) or -j for face j of collidedShape (it has 4), got 99')
    broken:setEdgeIndex(-5)
    raisesAt(function() S.ite(broken) end, 'got -5')
    broken:setEdgeIndex(1.5)
    raisesAt(function() S.ite(broken) end, 'got 1.5')
    broken:setEdgeIndex(-4)
    assert.is_table(S.ite(broken))
    local round = S.AT(box, H.Circle(6, 0, 3)):setEdgeIndex(2)
    assert.is_table(S.ite(round)) -- (face 2 of the box: in range)
    round = S.AT(H.Circle(6, 0, 3), box):setEdgeIndex(1) -- a circle has no faces
    raisesAt(function() S.ite(round) end, 'face i of colliderShape (it has 0)')
    local hand = S.AT(box, other)
    hand.depth = 'deep'
    raisesAt(function() S.ite(hand) end, 'strike.ite: the MTV\'s nx, ny and depth must be numbers')
  end)

  it('S.ettle and S.hove reject MTVs whose bodies are missing or fake', function()
    raisesAt(function() S.ettle({ x = 1, y = 2 }) end, 'strike.ettle: the MTV\'s collider must be a strike collider'
      .. ' or shape (as in an MTV from S.AT or S.triking), got nil')
    raisesAt(function() S.ettle(S.MTV(1, 0)) end, 'strike.ettle: the MTV\'s collider must be a strike collider or'
      .. ' shape (as in an MTV from S.AT or S.triking), got false')
    raisesAt(function() S.ettle({ x = 1, y = 2, collider = box, collided = {} }) end,
      'strike.ettle: the MTV\'s collided must be a strike collider or shape (as in an MTV from S.AT or'
        .. ' S.triking), got table')
    raisesAt(function() S.hove({ x = 1, y = 2, collided = 5 }) end, 'strike.hove: the MTV\'s collided must be a strike'
      .. ' collider or shape (as in an MTV from S.AT or S.triking), got 5')
    raisesAt(function() S.hove(S.MTV(1, 0)) end, 'strike.hove: the MTV\'s collided must be')
    raisesAt(function() S.ettle(col) end, 'strike.ettle: argument 1 must be an MTV, got a collider')
    raisesAt(function() S.hove('mtv') end, 'strike.hove: argument 1 must be an MTV, got string "mtv"')
    local broken = S.AT(box, other)
    broken.x = 0 / 0
    raisesAt(function() S.ettle(broken) end, 'strike.ettle: the MTV\'s x and y must be finite numbers, got nan and 0')
    broken.x, broken.y = 1, math.huge
    raisesAt(function() S.hove(broken) end, 'strike.hove: the MTV\'s x and y must be finite numbers, got 1 and inf')
    nearList(geometry(other), { 3, -5, 13, -5, 13, 5, 3, 5 }) -- nothing moved
    local a = H.Circle(0, 0, 1)
    S.hove(S.MTV(2, 0, nil, a)) -- S.hove needs only the collided side
    nearList({ a:getCentroid() }, { 2, 0 })
    S.ettle(S.MTV(1, 0, a, a):setSeparating(true)) -- a separating MTV: nothing to do, nothing checked
  end)

  it('S.ircle and S.aabb reject fakes; an empty collider overlaps nothing', function()
    raisesAt(function() S.ircle(box, { kind = 'circle' }) end,
      'strike.ircle: argument 2 must be a strike collider or shape, got table')
    raisesAt(function() S.aabb({ type = 'collider' }, box) end,
      'strike.aabb: argument 1 must be a strike collider or shape, got table')
    -- (a table's `type` is its own: strike reads its classes' marker, never an instance's)
    raisesAt(function() S.aabb(box, { type = 'shape' }) end,
      'strike.aabb: argument 2 must be a strike collider or shape, got table')
    raisesAt(function() S.ircle(m, box) end, 'strike.ircle: argument 1 must be a strike collider or shape, got table')
    local empty = T.Collider()
    assert.is_false(S.aabb(empty, box)) -- its zero box sits at (0, 0), inside box
    assert.is_false(S.ircle(box, empty))
    assert.is_false(S.aabb(T.Collider(T.Collider()), box))
    assert.is_false(S.triking(empty, box))
  end)

  it('shape:getVertices(out) takes a table or nil', function()
    raisesAt(function() box:getVertices('x') end,
      'strike.Shape:getVertices: out must be a table or nil, got string "x"')
    raisesAt(function() H.Circle(0, 0, 1):getVertices(5) end, 'strike.Shape:getVertices: out must be a table or nil')
    raisesAt(function() box:getVertices(other) end, 'out must be a table or nil, got a shape')
    nearList(geometry(other), { 3, -5, 13, -5, 13, 5, 3, 5 }) -- untouched
    local t = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 }
    assert.equals(t, box:getVertices(t))
    assert.equals(8, #t)
  end)

  it('MTV:set takes an MTV', function()
    raisesAt(function() S.MTV():set(nil) end, 'strike.MTV:set: argument 1 must be an MTV, got nil')
    raisesAt(function() S.MTV():set(box) end, 'strike.MTV:set: argument 1 must be an MTV, got table')
  end)

  it('S.trikers.Chain names the loop flag when it is not a boolean, in either form', function()
    raisesAt(function() T.Chain(0, 0, 10, 0, 20, 5, 'yes') end,
      'strike.Chain: loop must be a boolean, got string "yes"')
    raisesAt(function() T.Chain({ 0, 0, 10, 0, 20, 5 }, 'yes') end, 'strike.Chain: loop must be a boolean, got string')
    raisesAt(function() T.Chain(0, 0, 10, 0, 20, 5, {}) end, 'strike.Chain: loop must be a boolean, got table')
    raisesAt(function() T.Chain({ 0, 0, 10, 0, 20, 5, true }) end, 'strike.Chain: the loop flag goes after the table')
    raisesAt(function() T.Chain(0, 0, 10, 0, 20) end, 'strike.Chain: expected x, y pairs, got an odd number of values')
    raisesAt(function() T.Chain(0, 0, 10, 0, 20, 5, 1) end, 'expected x, y pairs, got an odd number of values (7)')
    assert.is_true(T.Chain(0, 0, 10, 0, 20, 5, true):isLoop())
    assert.is_false(T.Chain(0, 0, 10, 0, 20, 5, nil):isLoop())
  end)

  it('shape methods name the function for wrong types, NaN and infinity', function()
    raisesAt(function() box:getSupport('a', 0) end, 'strike.Shape:getSupport: nx must be a finite number')
    raisesAt(function() H.Circle(0, 0, 1):getSupport(0, 0 / 0) end, 'strike.Shape:getSupport: ny must be a finite')
    raisesAt(function() H.Circle(0, 0, 1):ipairs(col) end, 'strike.Circle:ipairs: other must be a strike shape or nil,'
      .. ' got a collider')
    raisesAt(function() H.Circle(0, 0, 1):vecs(5) end, 'strike.Circle:vecs: other must be a strike shape or nil, got 5')
    raisesAt(function() H.Circle(0, 0, 1):ipairs({ type = 'shape' }) end,
      'other must be a strike shape or nil, got table')
    raisesAt(function() box:copy('a', 0) end, 'strike.Shape:copy: x must be a finite number, got string "a"')
    raisesAt(function() box:copy(1) end, 'strike.Shape:copy: y must be a finite number, got nil')
    raisesAt(function() box:copy(0, 0, math.huge) end, 'strike.Shape:copy: angle must be a finite number, got inf')
    raisesAt(function() col:copy(0 / 0, 0) end, 'strike.Collider:copy: x must be a finite number, got nan')
    raisesAt(function() box:translate(0 / 0, 0) end, 'strike.Shape:translate: dx must be a finite number, got nan')
    raisesAt(function() col:rotate(math.huge) end, 'strike.Collider:rotate: angle must be a finite number, got inf')
    raisesAt(function() box:project('x', 0) end, 'strike.Shape:project: nx must be a finite number')
    raisesAt(function() box:containsPoint({}) end, 'strike.Shape:containsPoint: point x must be a finite number')
    raisesAt(function() S.MTV(0 / 0, 0) end, 'strike.MTV: dx must be a finite number, got nan')
    raisesAt(function() S.MTV(1, 0):scale('2') end, 'strike.MTV:scale: factor must be a finite number')
  end)

  it('Collider:add and remove name what they expected', function()
    raisesAt(function() T.Collider({ kind = 'polygon' }) end,
      'strike.Collider:add: argument 1 must be a strike shape or collider, got table')
    raisesAt(function() T.Collider(nil) end,
      'strike.Collider:add: argument 1 must be a strike shape or collider, got nil')
    raisesAt(function() col:add(m) end, 'strike.Collider:add: argument 1 must be a strike shape or collider, got table')
    raisesAt(function() col:add(col) end, 'strike.Collider:add: argument 1 would contain itself')
    raisesAt(function() T.Collider():remove(1) end,
      'strike.Collider:remove: index must be an integer from 1 to 0, got 1')
    raisesAt(function() col:remove('1') end, 'strike.Collider:remove: index must be an integer from 1 to 1, got string')
  end)
end)
