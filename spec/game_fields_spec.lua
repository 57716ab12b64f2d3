-- Game data on bodies (README, "Your data on bodies"): strike keeps its own state on a body
-- under its integer keys and names starting with `_`; every other name is the game's.
--
-- The same world is built and used twice, once plain and once with 30 field names every game
-- uses set on every body and every member (before they join a collider, after, before and
-- after the bodies join a space, and set again between the steps, to values that look like
-- strike's own: `type = 'shape'`, `kind = 'circle'`, `shapes = {}`, `parent = <a collider>`).
-- Every answer of both runs is written down, bodies by their order of creation, numbers to
-- the last bit, and the two transcripts must be equal. Then: strike left every game field as
-- the game set it, wrote no name of its own that does not start with `_`, and a copy shares
-- the game's values. The second half overwrites each name strike reserves and expects an
-- error naming it at the next call that relies on it.
local S = require('strike')
local expect = require('spec.helpers.expect')
local raisesAt = expect.raisesAt
local H, T = S.hapes, S.trikers

-- (none of them is the name of a method: checked below)
local NAMES = {
  'type', 'kind', 'name', 'id', 'tag', 'parent', 'shapes', 'data', 'x', 'y', 'w', 'h', 'width', 'height', 'layer',
  'mask', 'group', 'sensor', 'owner', 'health', 'team', 'state', 'speed', 'vx', 'vy', 'dead', 'sprite', 'image',
  'body', 'world',
}

local RULE = 'fields starting with _ are strike\'s (README, "Your data on bodies")'

------------------------------------------------------------------ a world, written down

-- A world: its objects in order of creation (labels o1, o2, ...), whether the game sets its
-- fields, what it set (to check strike never wrote them) and the transcript.
local function newWorld(decorate)
  return { decorate = decorate, objects = {}, label = {}, game = {}, log = {}, space = false, copyOf = {},
    copyParent = {}, shared = {} }
end

local function label(W, obj)
  if not W.label[obj] then
    W.objects[#W.objects + 1] = obj
    W.label[obj] = 'o' .. #W.objects
  end
  return obj
end

-- Label a body and everything it holds, depth first in order.
local function labelTree(W, body)
  label(W, body)
  if body.getShapeCount then
    for _, c in ipairs({ body:unpack() }) do labelTree(W, c) end
  end
  return body
end

-- The game's value for field `name` of object number `i` at step `p`: numbers, strings,
-- booleans, tables, and values strike could mistake for its own, strike objects included.
local function valueFor(W, name, i, p)
  local k = (i * 3 + p * 7 + #name) % 6
  local objs = W.objects
  local other = objs[(i * 5 + p) % #objs + 1]
  if name == 'type' then return ({ 'shape', 'collider', 'mtv', 'space', 'enemy', 'Rectangle' })[k + 1] end
  if name == 'kind' then return ({ 'circle', 'polygon', 'chain', 'rounded', 'orc', 'specBlob' })[k + 1] end
  if name == 'name' then return ({ 'Circle', 'Collider', 'Shape', 'MTV', 'hero', '' })[k + 1] end
  if name == 'parent' or name == 'owner' or name == 'body' then
    return ({ other, other, other, { parent = true }, false, 'none' })[k + 1]
  end
  if name == 'shapes' then return ({ {}, { other }, { other, other }, {}, { n = 1 }, 0 })[k + 1] end
  if name == 'world' then return W.space or { bodies = {} } end
  if name == 'sensor' or name == 'dead' then return k % 2 == 0 end
  if name == 'mask' then return ({ { 'wall' }, {}, false, 'wall', 3, { wall = true } })[k + 1] end
  if name == 'layer' or name == 'tag' or name == 'team' or name == 'state' then
    return ({ 'default', 'wall', 'player', '', 'zone', 'enemy' })[k + 1]
  end
  return ({ i * 1.5 + p, -1, 0, 1e300, 'wall', { n = i } })[k + 1] -- (id, x, y, w, h, data, ...)
end

-- Set every game field of `obj` (the decorated world only), remembering the values.
local function decorate(W, obj, p)
  if not W.decorate then return obj end
  local i = 0
  for n, o in ipairs(W.objects) do
    if o == obj then i = n end
  end
  local shadow = W.game[obj] or {}
  W.game[obj] = shadow
  for _, name in ipairs(NAMES) do
    local v = valueFor(W, name, i, p)
    obj[name] = v
    shadow[name] = v
  end
  return obj
end

local function decorateTree(W, body, p)
  decorate(W, body, p)
  if body.getShapeCount then
    for _, c in ipairs({ body:unpack() }) do decorateTree(W, c, p) end
  end
end

local function decorateAll(W, p)
  for _, o in ipairs(W.objects) do decorate(W, o, p) end
end

-- A value written down: strike's objects by label, numbers to the last bit, tables by their
-- entries in a fixed order (names starting with `_`, strike's bookkeeping such as an MTV's
-- pose stamps, left out).
local function ser(W, v, depth)
  local t = type(v)
  if t == 'number' then
    if v ~= v then return 'nan' end
    return ('%.17g'):format(v)
  elseif t == 'string' then
    return ('%q'):format(v)
  elseif t ~= 'table' then
    return tostring(v)
  end
  if W.label[v] then return W.label[v] end
  if v == W.space then return 'space' end
  depth = (depth or 0) + 1
  assert(depth < 8, 'ser: too deep')
  local parts = {}
  for k, x in pairs(v) do
    if not (type(k) == 'string' and k:sub(1, 1) == '_') then
      parts[#parts + 1] = ser(W, k, depth) .. '=' .. ser(W, x, depth)
    end
  end
  table.sort(parts)
  return '{' .. table.concat(parts, ',') .. '}'
end

local unpack = table.unpack or unpack -- luacheck: ignore 113 143
local function pack(...) return { n = select('#', ...), ... } end

-- Write down the results of fn(...) (or its error, without the position).
local function R(W, tag, fn, ...)
  local r = pack(pcall(fn, ...))
  local parts = { tag }
  if not r[1] then
    parts[2] = 'error ' .. tostring(r[2]):gsub('^[^:]*:%d+: ', '')
  else
    for i = 2, r.n do parts[#parts + 1] = ser(W, r[i]) end
  end
  W.log[#W.log + 1] = table.concat(parts, ' ')
  return select(2, unpack(r, 1, r.n))
end

------------------------------------------------------------------ the world and its uses

local function isCollider(b) return b.getShapeCount ~= nil end

-- Every getter of a body, and of each of its members.
local function getters(W, b, tag)
  local rs = { 'getCentroid', 'getArea', 'getAreaCentroid', 'getRadius', 'getBbox', 'getBounds', 'getAngle', 'getRoot',
    'getParent', 'unpack' }
  for _, m in ipairs(rs) do R(W, tag .. ':' .. m, function() return b[m](b) end) end
  R(W, tag .. ':project', function() return b:project(0.6, 0.8) end)
  if isCollider(b) then
    R(W, tag .. ':getShapeCount', function() return b:getShapeCount() end)
    R(W, tag .. ':elems', function()
      local list = {}
      for s in b:elems() do list[#list + 1] = s end
      return list
    end)
    R(W, tag .. ':ipairs', function()
      local list = {}
      for p, s, i in b:ipairs() do list[#list + 1] = { p, s, i } end
      return list
    end)
    if b.isLoop then R(W, tag .. ':isLoop', function() return b:isLoop() end) end
    if b.getDimensions then R(W, tag .. ':getDimensions', function() return b:getDimensions() end) end
    for _, c in ipairs({ b:unpack() }) do getters(W, c, tag .. '/' .. W.label[c]) end
  else
    for _, m in ipairs({ 'getScale', 'getRounding', 'getKind', 'getVertexCount', 'getVertices' }) do
      R(W, tag .. ':' .. m, function() return b[m](b) end)
    end
    R(W, tag .. ':v1', function() return b:getVertex(1), b:getEdge(1), b:getNormal(1), b:getSupport(0.6, 0.8) end)
    R(W, tag .. ':edges', function()
      local list = {}
      for i, x1, y1, x2, y2 in b:ipairs() do list[#list + 1] = { i, x1, y1, x2, y2 } end
      for i, dx, dy in b:vecs() do list[#list + 1] = { i, dx, dy } end
      return list
    end)
    if b.getGhostVertices then R(W, tag .. ':ghosts', function() return b:getGhostVertices(), b:isConvex(1) end) end
    if b.getLength then R(W, tag .. ':getLength', function() return b:getLength() end) end
  end
end

-- Points and rays about a body.
local function probes(W, b, tag)
  local cx, cy = b:getCentroid()
  local r = b:getRadius() + 1
  for _, d in ipairs({ { 0, 0 }, { 0.3, 0.1 }, { -0.5, 0.4 }, { 0.9, -0.2 }, { 2, 0 } }) do
    R(W, tag .. ':containsPoint', function() return b:containsPoint(cx + d[1] * r, cy + d[2] * r) end)
  end
  for _, a in ipairs({ 0, 1.1, 2.5, 4 }) do
    local ox, oy = cx + 2 * r * math.cos(a), cy + 2 * r * math.sin(a)
    R(W, tag .. ':rayCast', function() return b:rayCast(ox, oy, cx - ox, cy - oy) end)
    R(W, tag .. ':segmentCast', function() return b:segmentCast(ox, oy, cx, cy) end)
    R(W, tag .. ':rayIntersections', function() return b:rayIntersections(ox, oy, cx - ox, cy - oy) end)
    R(W, tag .. ':rayIntersects', function() return b:rayIntersects(ox, oy, cx - ox, cy - oy) end)
    R(W, tag .. ':inside', function() return b:rayCast(cx, cy, math.cos(a), math.sin(a)) end)
  end
end

-- The pairwise answers between bodies: S.triking (and S.ite on it), S.aabb, S.ircle, S.weep,
-- S.eparation; S.AT and S.ite between leaves.
local function pairsOf(W, bodies, tag)
  for i = 1, #bodies do
    for j = 1, #bodies do
      if i ~= j then
        local a, b = bodies[i], bodies[j]
        local t = tag .. ':' .. W.label[a] .. ',' .. W.label[b]
        local m = R(W, t .. ':triking', function() return S.triking(a, b) end)
        if m then R(W, t .. ':ite', function() return S.ite(m) end) end
        R(W, t .. ':aabb', function() return S.aabb(a, b), S.ircle(a, b) end)
        local ax, ay = a:getCentroid()
        local bx, by = b:getCentroid()
        if (i + j) % 3 == 0 then
          R(W, t .. ':weep', function() return S.weep(a, (bx - ax) * 1.5, (by - ay) * 1.5, b) end)
          R(W, t .. ':eparation', function() return S.eparation(a, b) end)
        end
        if (i + j) % 7 == 0 then
          R(W, t .. ':weepTurn', function() return S.weep(a, bx - ax, by - ay, b, 0.7) end)
        end
      end
    end
  end
end

local function leavesOf(b)
  if not isCollider(b) then return { b } end
  local list = {}
  for s in b:elems() do list[#list + 1] = s end
  return list
end

local function leafPairs(W, bodies, tag)
  local leaves = {}
  for _, b in ipairs(bodies) do
    for _, s in ipairs(leavesOf(b)) do leaves[#leaves + 1] = s end
  end
  for i = 1, #leaves, 2 do
    for j = 2, #leaves, 3 do
      local a, b = leaves[i], leaves[j]
      local m = R(W, tag .. ':AT:' .. W.label[a] .. ',' .. W.label[b], function() return S.AT(a, b) end)
      if m and not m.separating then R(W, tag .. ':ite', function() return S.ite(m) end) end
      R(W, tag .. ':triking(leaves)', function() return S.triking(a, b) end)
    end
  end
end

-- Every kind of body: each shape kind bare, rounded shapes, single-shape colliders, Capsule,
-- Chain (open and closed), Concave, a compound, nested colliders (an empty one among them).
local function build(W)
  local bodies = {}
  local function add(b)
    bodies[#bodies + 1] = labelTree(W, b)
    return b
  end
  add(H.Rectangle(0, 0, 10, 6))
  add(H.Rectangle(14, 2, 12, 8, 0.3, 2))
  add(H.Circle(30, 0, 5))
  add(H.Capsule(42, 0, 6, 16, 0.2))
  add(H.ConvexPolygon(52, -4, 62, -4, 64, 4, 56, 8))
  add(H.ConvexPolygon({ 66, 0, 76, 0, 71, 9, radius = 1.5 }))
  add(H.RegularPolygon(84, 0, 6, 6, 0.1))
  add(H.Ellipse(96, 2, 8, 4))
  add(H.Edge(100, -5, 110, 5))
  add(H.Point(8, 2))
  add(T.Rectangle(4, 10, 10, 6))
  add(T.Rectangle(20, 8, 12, 8, 0.3, 2))
  add(T.Circle(33, 9, 5))
  add(T.Capsule(45, 12, 6, 16, 0.2))
  add(T.ConvexPolygon(55, 6, 65, 6, 67, 14, 59, 18))
  add(T.RegularPolygon(80, 9, 5, 6))
  add(T.Ellipse(92, 10, 8, 4))
  add(T.Edge(100, 6, 112, 12))
  add(T.Point(62, 10))
  add(T.Chain(-10, 30, 20, 30, 50, 36, 80, 30))
  add(T.Chain({ 84, 24, 110, 24, 110, 44, 84, 44 }, true))
  add(T.Concave(0, 40, 30, 40, 30, 60, 22, 60, 22, 48, 0, 48))
  -- a compound whose members carry the game's fields before they join it
  local m1, m2, m3 = label(W, H.Circle(40, 46, 6)), label(W, H.Rectangle(50, 46, 10, 10)),
    label(W, H.Edge(34, 56, 64, 56))
  decorate(W, m1, 0)
  decorate(W, m2, 0)
  decorate(W, m3, 0)
  add(T.Collider(m1, m2, m3))
  -- nested colliders
  local inner2 = T.Collider(H.Circle(72, 50, 3), H.ConvexPolygon(74, 46, 80, 46, 80, 52))
  local inner1 = T.Collider(H.Rectangle(66, 52, 8, 8), inner2, T.Capsule(86, 50, 4, 10))
  add(T.Collider(inner1, H.Circle(92, 56, 4), T.Collider()))
  return bodies
end

-- The whole use of a world, written down in W.log.
local function run(W)
  local bodies = build(W)
  decorateAll(W, 1)
  -- the bodies alone
  for _, b in ipairs(bodies) do
    getters(W, b, W.label[b])
    probes(W, b, W.label[b])
  end
  pairsOf(W, bodies, 'start')
  leafPairs(W, bodies, 'start')
  -- transforms, of bodies and of members nested in them
  decorateAll(W, 2)
  for i, b in ipairs(bodies) do
    local cx, cy = b:getCentroid()
    R(W, 'translate', function() return b:translate(1.5, -0.5) end)
    R(W, 'rotate', function() return b:rotate(0.2 * i, cx + 1, cy) end)
    R(W, 'scale', function() return b:scale(1.1) end)
    R(W, 'translateTo', function() return b:translateTo(cx + 0.25, cy - 0.75) end)
    R(W, 'rotateTo', function() return b:rotateTo(0.5) end)
    if isCollider(b) and b:getShapeCount() > 1 then
      local leaf = leavesOf(b)[2]
      R(W, 'member', function() return leaf:translate(0.5, 0.5):rotate(0.1) end)
    end
    getters(W, b, 'moved ' .. W.label[b])
    probes(W, b, 'moved ' .. W.label[b])
  end
  pairsOf(W, bodies, 'moved')
  -- members added and removed, merged; copies
  decorateAll(W, 3)
  local compound, nested, concave = bodies[23], bodies[24], bodies[22]
  local extra = label(W, H.Circle(60, 60, 2))
  decorate(W, extra, 3)
  R(W, 'add', function() return nested:add(extra) end)
  local inner1 = (nested:unpack())
  local removed = R(W, 'remove', function() return inner1:remove(1) end)
  R(W, 'add back', function() return compound:add(removed) end)
  local squares = labelTree(W, T.Collider(H.Rectangle(0, 80, 10, 10), H.Rectangle(10, 80, 10, 10), H.Circle(30, 80, 3)))
  decorateTree(W, squares, 3)
  R(W, 'consolidate', function() return squares:consolidate(), concave:consolidate() end)
  labelTree(W, squares)
  bodies[#bodies + 1] = squares
  local copies = {}
  -- (a copy and its members, each with what it is a copy of)
  -- (as it is made, a copy holds the very values of the game's fields its original holds)
  local function copied(c, b, parent)
    W.copyOf[c] = b
    W.copyParent[c] = parent or false
    W.shared[c] = {}
    for _, name in ipairs(NAMES) do W.shared[c][name] = rawequal(rawget(c, name), rawget(b, name)) end
    if isCollider(c) then
      local from = { b:unpack() }
      for k, m in ipairs({ c:unpack() }) do copied(m, from[k], c) end
    end
    return labelTree(W, c)
  end
  for i, b in ipairs(bodies) do
    local c = copied(b:copy(), b)
    local c2 = copied(b:copy(i, -i, 0.1 * i), b)
    copies[#copies + 1] = c
    copies[#copies + 1] = c2
    getters(W, c, 'copy ' .. W.label[b])
    getters(W, c2, 'copy2 ' .. W.label[b])
  end
  W.copies = copies
  pairsOf(W, { bodies[1], bodies[13], bodies[23], bodies[24], copies[1], copies[46], copies[48] }, 'copies')
  -- a space: bodies added with their fields set before, others set after
  local space = S.pace()
  W.space = space
  local events = {}
  for _, ev in ipairs({ 'begin', 'stay', 'end' }) do
    space:on(ev, function(a, b, rec) events[#events + 1] = { ev, a, b, rec.mtv, rec.sensor, rec.contacts } end)
  end
  decorateAll(W, 4)
  local layers = { 'default', 'wall', 'player' }
  for i = 1, #bodies do
    local b = bodies[i]
    if i % 2 == 0 then decorateTree(W, b, 5) end -- (some just before they join)
    R(W, 'space:add', function()
      return space:add(b, { layer = layers[i % 3 + 1], sensor = i % 11 == 0, group = i % 13 == 0 and -1 or 0 })
    end)
  end
  decorateAll(W, 6) -- (and every one after)
  local function queries(tag)
    R(W, tag .. ':count', function() return space:count(), space:bodies() end)
    local n = select(2, R(W, tag .. ':collisions', function() return space:collisions() end))
    R(W, tag .. ':events', function() return events, n end)
    for k = #events, 1, -1 do events[k] = nil end
    for i, b in ipairs(bodies) do
      local cx, cy = b:getCentroid()
      R(W, tag .. ':check', function() return space:check(b) end)
      R(W, tag .. ':get', function() return space:has(b), space:get(b) end)
      R(W, tag .. ':queryPoint', function() return space:queryPoint(cx + 0.5, cy - 0.5) end)
      R(W, tag .. ':queryShape', function() return space:queryShape(b) end)
      R(W, tag .. ':cast', function() return space:cast(b, 7, -3 + i % 5) end)
    end
    for y = -10, 90, 20 do
      R(W, tag .. ':queryRect', function() return space:queryRect(-20, y, 140, 12) end)
      R(W, tag .. ':rayCast', function() return space:rayCast(-30, y, 1, 0.05) end)
      R(W, tag .. ':rayCastAll', function() return space:rayCastAll(-30, y, 1, 0.05) end)
      R(W, tag .. ':rayCastAll back', function() return space:rayCastAll(150, y, -1, -0.02, 140) end)
    end
  end
  queries('space')
  R(W, 'set', function() return space:set(bodies[3], { layer = 'player', mask = { 'wall' } }), space:get(bodies[3]) end)
  for i, b in ipairs(bodies) do
    if i % 4 == 1 and not b.isLoop then
      local cx, cy = b:getCentroid()
      R(W, 'move ' .. W.label[b], function() return space:move(b, cx + 9, cy + 4) end)
    end
  end
  decorateAll(W, 7)
  R(W, 'nested member moves', function() return leavesOf(bodies[24])[3]:translate(-2, 1), bodies[23]:rotate(0.3) end)
  queries('moved')
  R(W, 'remove', function() return space:remove(bodies[5]), space:remove(bodies[23]), space:remove(bodies[24]) end)
  decorateAll(W, 8)
  queries('removed')
  R(W, 'add again', function() return space:add(bodies[23]), space:add(bodies[24]), space:add(copies[1]) end)
  queries('again')
  return W
end

------------------------------------------------------------------ the specs

describe('game data on bodies', function()
  it('the 30 names are no method of any body class', function()
    local classes = { require('strike.base.Shape'), require('strike.base.VertexShape'),
      require('strike.base.ChainSegment'), T.Collider }
    for _, cls in pairs(H) do classes[#classes + 1] = cls end
    for _, name in ipairs({ 'Rectangle', 'Circle', 'Capsule', 'Chain', 'Concave', 'Edge', 'Point' }) do
      classes[#classes + 1] = T[name]
    end
    for _, cls in ipairs(classes) do
      for _, name in ipairs(NAMES) do
        assert.is_not_function(cls[name], name)
      end
    end
    assert.equals(30, #NAMES)
  end)

  local plain, decorated
  setup(function()
    plain = run(newWorld(false))
    decorated = run(newWorld(true))
  end)

  it('every answer is the same with the game\'s fields set, bit for bit', function()
    assert.is_true(#plain.log > 5000, 'answers written down: ' .. #plain.log)
    for i = 1, math.max(#plain.log, #decorated.log) do
      if plain.log[i] ~= decorated.log[i] then
        error(('answer %d differs:\nwithout the fields: %s\nwith them:          %s'):format(i, tostring(plain.log[i]),
          tostring(decorated.log[i])))
      end
    end
  end)

  it('the game set them on every kind of body, bare, in colliders and in the space', function()
    assert.equals(#plain.objects, #decorated.objects)
    local classes = {}
    for _, o in ipairs(decorated.objects) do
      assert.is_true(decorated.game[o] ~= nil or decorated.copyOf[o] ~= nil, decorated.label[o])
      if decorated.game[o] then classes[getmetatable(o)] = true end
    end
    for _, cls in ipairs({ H.Rectangle, H.Circle, H.Capsule, H.ConvexPolygon, H.RegularPolygon, H.Ellipse, H.Edge,
      H.Point, require('strike.base.ChainSegment'), T.Rectangle, T.Circle, T.Capsule, T.ConvexPolygon,
      T.RegularPolygon, T.Ellipse, T.Edge, T.Point, T.Chain, T.Concave, T.Collider }) do
      assert.is_true(classes[cls], cls.name)
    end
  end)

  it('strike never wrote a game field: each holds what the game set last', function()
    local checked = 0
    for o, shadow in pairs(decorated.game) do
      for _, name in ipairs(NAMES) do
        assert.is_true(rawequal(rawget(o, name), shadow[name]), decorated.label[o] .. '.' .. name)
        checked = checked + 1
      end
    end
    assert.is_true(checked > 30 * 60, 'fields checked: ' .. checked)
  end)

  it('strike names no field of its own without `_` (its other keys are integers)', function()
    local seen = 0
    for _, o in ipairs(plain.objects) do
      for k in pairs(o) do
        if type(k) ~= 'number' then
          assert.equals('_', tostring(k):sub(1, 1), plain.label[o] .. ' has the field ' .. tostring(k))
          seen = seen + 1
        else
          assert.equals(k, math.floor(k))
        end
      end
    end
    assert.is_true(seen > 100)
  end)

  it('copies share the game\'s values by reference, members too, and belong to no collider', function()
    local W = decorated
    local shared = 0
    for c, orig in pairs(W.copyOf) do
      assert.is_not_nil(W.game[orig], W.label[orig])
      for _, name in ipairs(NAMES) do
        assert.is_true(W.shared[c][name], W.label[c] .. '.' .. name)
        shared = shared + 1
      end
      assert.equals(W.copyParent[c] or nil, c:getParent())
    end
    assert.is_true(shared > 30 * 60, 'fields compared: ' .. shared)
  end)
end)

------------------------------------------------------------------ strike's names, overwritten

-- The error for `owner`'s field `field`, now `now` (as check.describe writes it).
local function changed(fname, owner, field, now)
  return ('%s: %s field %s was changed (now %s); %s'):format(fname, owner, field, now, RULE)
end

describe('a name strike reserves, overwritten by the game', function()
  local function box(x, y) return T.Rectangle(x or 0, y or 0, 10, 10) end

  describe('_type (the class marker, read through the instance)', function()
    it('is an error where strike reads it: the space\'s and S.weep\'s body checks', function()
      local s, c = H.Circle(0, 0, 5), box()
      s._type, c._type = 'enemy', 'shape'
      local sp = S.pace()
      raisesAt(function() sp:add(s) end, changed('strike.Space:add', "argument 1's", '_type', 'string "enemy"'))
      raisesAt(function() S.weep(c, 1, 0, s) end, changed('strike.weep', "argument 1's", '_type', 'string "shape"'))
      raisesAt(function() S.eparation(box(50), c) end, changed('strike.eparation', "argument 2's", '_type',
        'string "shape"'))
    end)

    it('is never a wrong answer where strike does not read it', function()
      local a, b = box(), box(8, 0)
      local want = S.triking(a, b)
      a._type = 'collider!'
      local got = S.triking(a, b)
      assert.equals(want.x, got.x)
      assert.equals(want.y, got.y)
      assert.equals(5, a:getCentroid() + 5)
    end)

    it('of a body in a space: its next space call', function()
      local sp, c = S.pace(), box()
      sp:add(c)
      c._type = {}
      raisesAt(function() sp:check(c) end, changed('strike.Space:check', "argument 1's", '_type', 'table'))
      raisesAt(function() sp:remove(c) end, changed('strike.Space:remove', "argument 1's", '_type', 'table'))
    end)
  end)

  describe('_kind (the narrow phase\'s dispatch)', function()
    it('of a bare shape: S.AT, S.triking, S.weep, S.eparation, its rays', function()
      local s, t = H.Rectangle(0, 0, 10, 10), H.Circle(4, 0, 5)
      s._kind = 'orc'
      raisesAt(function() S.AT(s, t) end, changed('strike.AT', "argument 1's", '_kind', 'string "orc"'))
      raisesAt(function() S.AT(t, s) end, changed('strike.AT', "argument 2's", '_kind', 'string "orc"'))
      raisesAt(function() S.triking(t, s) end, changed('strike.triking', "argument 2's", '_kind', 'string "orc"'))
      raisesAt(function() S.weep(s, 1, 0, t) end, changed('strike.weep', "argument 1's", '_kind', 'string "orc"'))
      -- (a sweep's leaves, checked before anything reads their kind)
      raisesAt(function() S.weep(t, 1, 0, T.Collider(s)) end, changed('strike.weep', 'argument 4 holds a shape whose',
        '_kind', 'string "orc"'))
      raisesAt(function() S.eparation(t, s) end, changed('strike.eparation', "argument 2's", '_kind',
        'string "orc"'))
      raisesAt(function() s:rayCast(-20, 0, 1, 0) end, changed('strike', "a shape's", '_kind', 'string "orc"'))
      raisesAt(function() s:rayCast(-1e9, 0, 1, 0) end, changed('strike', "a shape's", '_kind', 'string "orc"'))
      s._kind = nil
      raisesAt(function() S.AT(s, t) end, changed('strike.AT', "argument 1's", '_kind', 'nil'))
    end)

    it('of a member: S.triking, S.weep and S.eparation name the body that holds it', function()
      local c, d = box(), box(8, 0)
      local leaf = (c:unpack())
      leaf._kind = 'circle?'
      local msg = changed('strike.triking', 'argument 1 holds a shape whose', '_kind', 'string "circle?"')
      raisesAt(function() S.triking(c, d) end, msg)
      raisesAt(function() S.triking(d, c) end, msg:gsub('argument 1', 'argument 2'))
      -- bodies apart: the sweep's own check of its leaves
      local far = box(100, 0)
      raisesAt(function() S.weep(c, 1, 0, far) end, changed('strike.weep', 'argument 1 holds a shape whose', '_kind',
        'string "circle?"'))
      raisesAt(function() S.weep(far, 1, 0, c) end, changed('strike.weep', 'argument 4 holds a shape whose', '_kind',
        'string "circle?"'))
      raisesAt(function() S.eparation(far, c) end, changed('strike.eparation', 'argument 2 holds a shape whose',
        '_kind', 'string "circle?"'))
      local compound = T.Collider(H.Circle(0, 0, 1), H.Circle(5, 0, 1))
      select(2, compound:unpack())._kind = 'x'
      raisesAt(function() S.eparation(compound, far) end, changed('strike.eparation', 'argument 1 holds a shape whose',
        '_kind', 'string "x"'))
      raisesAt(function() c:rayCast(-20, 0, 1, 0) end, changed('strike', "a shape's", '_kind', 'string "circle?"'))
    end)

    it('of members of compounds: every loop of S.triking, and S.ite\'s', function()
      local a = T.Collider(H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10))
      local b = T.Collider(H.Circle(4, 8, 4), H.Circle(200, 0, 2))
      local m = S.triking(a, b)
      assert.is_table(m)
      local a1, a2 = a:unpack()
      local b1, b2 = b:unpack()
      -- the far member of b: its box meets nothing, but the outline rule reads its kind
      b2._kind = 7
      raisesAt(function() S.triking(a, b) end, changed('strike.triking', 'argument 2 holds a shape whose', '_kind',
        '7'))
      b2._kind = 'circle'
      b1._kind = false -- (a member whose box meets a's)
      raisesAt(function() S.triking(a, b) end, changed('strike.triking', 'argument 2 holds a shape whose', '_kind',
        'false'))
      b1._kind = 'circle'
      a2._kind = 'x'
      raisesAt(function() S.triking(a, b) end, changed('strike.triking', 'argument 1 holds a shape whose', '_kind',
        'string "x"'))
      a2._kind = 'polygon'
      local c = T.Collider(H.Circle(0, 20, 1), H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10))
      local chain = T.Chain(-20, 3, 40, 3)
      local hit = S.triking(chain, c)
      assert.is_table(hit)
      local seg = (chain:unpack())
      seg._kind = 'chain!'
      raisesAt(function() S.triking(chain, c) end, changed('strike.triking', 'argument 1 holds a shape whose',
        '_kind', 'string "chain!"'))
      raisesAt(function() S.triking(c, chain) end, changed('strike.triking', 'argument 2 holds a shape whose',
        '_kind', 'string "chain!"'))
      -- S.ite: the MTV's own shapes, then the other members it reads
      a1._kind = 'orc'
      raisesAt(function() S.ite(m) end, changed('strike.ite', "the MTV's colliderShape's", '_kind', 'string "orc"'))
      a1._kind = 'polygon'
      -- (a member that touches after the push, not the MTV's own: S.ite reads its kind too)
      local l = T.Collider(H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10))
      local lid = T.Rectangle(5, 7, 8, 6) -- (across both: each member touches it after the push)
      local m2 = S.triking(l, lid)
      local other = m2.colliderShape == (l:unpack()) and select(2, l:unpack()) or (l:unpack())
      local points = S.ite(m2)
      assert.equals(other, points[m2.colliderShape == points[1].colliderShape and points.count or 1].colliderShape)
      other._kind = 'orc'
      raisesAt(function() S.ite(m2) end, changed('strike.ite', "a shape's", '_kind', 'string "orc"'))
    end)

    it('of a body in a space: its next query that tests it', function()
      local sp, c = S.pace(), box()
      sp:add(c)
      sp:add(box(5, 0))
      local leaf = (c:unpack())
      leaf._kind = {}
      raisesAt(function() sp:collisions() end, changed('strike.triking', 'argument 1 holds a shape whose', '_kind',
        'table'))
      raisesAt(function() sp:rayCast(-20, 0, 1, 0) end, changed('strike', "a shape's", '_kind', 'table'))
    end)

    it('when drawn', function()
      rawset(_G, 'love', { graphics = { getColor = function() return 1, 1, 1, 1 end, setColor = function() end,
        polygon = function() end, line = function() end, circle = function() end } })
      finally(function() rawset(_G, 'love', nil) end)
      local c = box()
      local leaf = (c:unpack())
      leaf._kind = 'orc'
      raisesAt(function() c:draw() end, changed('strike:draw', "a shape's", '_kind', 'string "orc"'))
      raisesAt(function() S.howNorms(c) end, changed('strike.howNorms', "a shape's", '_kind', 'string "orc"'))
      raisesAt(function() S.howNorms({ _kind = 'polygon' }) end,
        'strike.howNorms: argument 1 must be a strike shape or collider, got table')
    end)
  end)

  describe('_parent', function()
    it('of a member: its transforms, S.triking and getRoot on it, adding it elsewhere', function()
      local c = T.Collider(H.Circle(0, 0, 5), H.Circle(20, 0, 5))
      c:getBbox()
      local m = (c:unpack())
      m._parent = { parent = true }
      raisesAt(function() m:translate(1, 0) end, changed('strike', "the shape's", '_parent', 'table'))
      raisesAt(function() S.triking(m, box(3, 0)) end, changed('strike', "the shape's", '_parent', 'table'))
      raisesAt(function() m:getRoot() end, changed('strike', "the shape's", '_parent', 'table'))
      raisesAt(function() T.Collider(m) end, changed('strike.Collider:add', "argument 1's", '_parent', 'table'))
      raisesAt(function() S.pace():add(m) end, changed('strike.Space:add', "argument 1's", '_parent', 'table'))
      raisesAt(function() c:ipairs()() end, changed('strike.Collider:ipairs', 'the collider holds a shape whose',
        '_parent', 'table'))
    end)

    it('of a bare shape or a root collider: a string or a table that is no collider holding it', function()
      local s = H.Circle(0, 0, 5)
      s._parent = 'none'
      raisesAt(function() s:translate(1, 0) end, changed('strike', "the shape's", '_parent', 'string "none"'))
      local c = box()
      c._parent = { shapes = { c } }
      raisesAt(function() c:getRoot() end, changed('strike', "the collider's", '_parent', 'table'))
      raisesAt(function() c:add(H.Point(0, 0)) end, changed('strike.Collider:add', "the collider's", '_parent',
        'table'))
      raisesAt(function() S.pace():add(c) end, changed('strike.Space:add', "argument 1's", '_parent', 'table'))
      local d = box()
      d:getBbox() -- (its caches fresh: a move of its leaf walks up through it)
      d._parent = {}
      raisesAt(function() d:translate(1, 0) end, changed('strike', 'the shape is held by a collider whose',
        '_parent', 'table'))
    end)

    it('of a nested collider: a move of a leaf below it', function()
      local inner = T.Collider(H.Circle(0, 0, 2))
      local outer = T.Collider(inner, H.Circle(10, 0, 2))
      outer:getBbox()
      inner._parent = {}
      local leaf = (inner:unpack())
      raisesAt(function() leaf:translate(1, 0) end, changed('strike', 'the shape is held by a collider whose',
        '_parent', 'table'))
      raisesAt(function() inner:add(H.Point(0, 0)) end, changed('strike.Collider:add', "the collider's", '_parent',
        'table'))
    end)

    it('a number there is an error too (Lua\'s own: strike does not test the type on this hot path)', function()
      local c = T.Collider(H.Circle(0, 0, 2), H.Circle(5, 0, 2))
      local m = (c:unpack())
      m._parent = 5
      assert.is_false(pcall(m.translate, m, 1, 0))
    end)
  end)

  describe('_shapes', function()
    it('nil: every method of the collider', function()
      local c = box()
      c._shapes = nil
      raisesAt(function() c:getArea() end, changed('strike.Collider:getArea', "the collider's", '_shapes', 'nil'))
      raisesAt(function() c:translate(1, 0) end, changed('strike.Collider:translate', "the collider's", '_shapes',
        'nil'))
      raisesAt(function() S.triking(c, box()) end, changed('strike', "the collider's", '_shapes', 'nil'))
    end)

    it('a list of the game\'s, or a number: every call that reads the children', function()
      for _, v in ipairs({ { { n = 1 } }, 5, 'list', true }) do
        local c = T.Collider(H.Circle(0, 0, 5), H.Circle(8, 0, 5))
        local other = box(3, 0)
        local want = S.triking(c, other)
        c._shapes = v
        local now = type(v) == 'table' and 'table' or type(v) == 'string' and 'string "list"' or tostring(v)
        -- (what strike has cached is still right: the same answer)
        local got = S.triking(c, other)
        assert.equals(want.x, got.x)
        raisesAt(function() c:unpack() end, changed('strike.Collider:unpack', "the collider's", '_shapes', now))
        raisesAt(function() c:add(H.Point(0, 0)) end, changed('strike.Collider:add', "the collider's", '_shapes',
          now))
        raisesAt(function() c:remove(1) end, changed('strike.Collider:remove', "the collider's", '_shapes', now))
        raisesAt(function() c:copy() end, changed('strike.Collider:copy', "the collider's", '_shapes', now))
        raisesAt(function() c:consolidate() end, changed('strike.Collider:consolidate', "the collider's", '_shapes',
          now))
        raisesAt(function() c:rotate(1) end, changed('strike', "the collider's", '_shapes', now))
        local leaf = c:_leafList()[1]
        leaf:translate(1, 0) -- (the caches go stale: the next reader needs the children)
        raisesAt(function() c:getArea() end, changed('strike', "the collider's", '_shapes', now))
        raisesAt(function() c:getBbox() end, changed('strike', "the collider's", '_shapes', now))
      end
    end)

    it('of a nested collider: the outer one\'s translation, which shifts its caches', function()
      local inner = T.Collider(H.Circle(0, 0, 2), H.Circle(3, 0, 2))
      local outer = T.Collider(inner, H.Circle(10, 0, 2))
      outer:getArea()
      outer:getBbox()
      inner._shapes = {}
      raisesAt(function() outer:translate(1, 0) end, changed('strike', "the collider's", '_shapes', 'table'))
    end)

    it('on a shape, which has no children', function()
      local s = H.Circle(0, 0, 2)
      s._shapes = {}
      raisesAt(function() T.Collider(s):getArea() end, changed('strike', "the shape's", '_shapes', 'table'))
    end)
  end)

  describe('_space and _sid (the space\'s bookkeeping)', function()
    local function inSpace(body)
      local sp = S.pace()
      sp:add(box(100, 100))
      sp:add(body)
      sp:queryPoint(0, 0) -- (the space has seen it: its next move reaches the space)
      return sp, body
    end

    it('_space: any value but the space the body is in, at its next move', function()
      local used = S.pace()
      used:add(box(500, 500)) -- (a space with bodies, but not this one)
      for _, v in ipairs({ {}, 'world', 5, true, used }) do
        local _, s = inSpace(H.Circle(0, 0, 5))
        s._space = v
        local now = type(v) == 'table' and 'table' or type(v) == 'string' and 'string "world"' or tostring(v)
        local owner = type(v) == 'table' and getmetatable(v) and "a body's" or "the shape's"
        raisesAt(function() s:translate(1, 0) end, changed('strike', owner, '_space', now))
        local _, c = inSpace(box())
        c._space = v
        owner = type(v) == 'table' and getmetatable(v) and "a body's" or 'the shape is held by a collider whose'
        raisesAt(function() c:translate(1, 0) end, changed('strike', owner, '_space', now))
      end
    end)

    it('_space: the space\'s calls about the body, nil included', function()
      for _, v in ipairs({ {}, false }) do
        local sp, c = inSpace(box())
        c._space = v or nil
        local now = v and 'table' or 'nil'
        raisesAt(function() sp:remove(c) end, changed('strike.Space:remove', "argument 1's", '_space', now))
        raisesAt(function() sp:has(c) end, changed('strike.Space:has', "argument 1's", '_space', now))
        raisesAt(function() sp:check(c) end, changed('strike.Space:check', "argument 1's", '_space', now))
        raisesAt(function() sp:cast(c, 1, 0) end, changed('strike.Space:cast', "argument 1's", '_space', now))
        raisesAt(function() sp:move(c, 1, 0) end, changed('strike.Space:move', "argument 1's", '_space', now))
        raisesAt(function() sp:get(c) end, changed('strike.Space:get', "argument 1's", '_space', now))
      end
    end)

    it('_space set on a body in no space: adding it to a space or a collider', function()
      local c = box()
      c._space = { 'world' }
      raisesAt(function() S.pace():add(c) end, changed('strike.Space:add', "argument 1's", '_space', 'table'))
      raisesAt(function() T.Collider(c) end, changed('strike.Collider:add', "argument 1's", '_space', 'table'))
      c._space = nil
      c._sid = 3
      raisesAt(function() S.pace():add(c) end, changed('strike.Space:add', "argument 1's", '_sid', '3'))
      raisesAt(function() T.Collider(c) end, changed('strike.Collider:add', "argument 1's", '_sid', '3'))
      assert.is_false(S.pace():has(c)) -- (its own question: it is in none)
    end)

    it('_sid: another body\'s id, a number of nothing, anything else', function()
      for _, v in ipairs({ 1, 99, 'id', {}, false }) do
        local sp, c = inSpace(box())
        c._sid = v
        local now = v == 1 and '1' or v == 99 and '99' or v == 'id' and 'string "id"' or v and 'table' or 'false'
        raisesAt(function() c:translate(1, 0) end, changed('strike', "a body's", '_sid', now))
        raisesAt(function() sp:remove(c) end, changed('strike.Space:remove', "argument 1's", '_sid', now))
        raisesAt(function() sp:set(c, { layer = 'x' }) end, changed('strike.Space:set', "argument 1's", '_sid', now))
        raisesAt(function() sp:has(c) end, changed('strike.Space:has', "argument 1's", '_sid', now))
        raisesAt(function() sp:check(c) end, changed('strike.Space:check', "argument 1's", '_sid', now))
        raisesAt(function() sp:cast(c, 1, 0) end, changed('strike.Space:cast', "argument 1's", '_sid', now))
        raisesAt(function() sp:add(c) end, changed('strike.Space:add', "argument 1's", '_sid', now))
      end
    end)

    it('_sid of a bare shape: its next move', function()
      local _, s = inSpace(H.Circle(0, 0, 5))
      s._sid = 1 -- (the other body's)
      raisesAt(function() s:translate(1, 0) end, changed('strike', "a body's", '_sid', '1'))
    end)
  end)

  describe('the other fields a body check reads', function()
    it('_pose of a shape, _single of a collider: named, not "got table"', function()
      local s = H.Rectangle(0, 0, 10, 10)
      s._pose = nil
      raisesAt(function() s:getArea() end, changed('strike.Shape:getArea', "the shape's", '_pose', 'nil'))
      raisesAt(function() S.AT(s, H.Circle(0, 0, 1)) end, changed('strike.AT', "argument 1's", '_pose', 'nil'))
      local c = box()
      c._single = nil
      raisesAt(function() S.triking(c, box()) end, changed('strike.triking', "argument 1's", '_single', 'nil'))
      raisesAt(function() S.aabb(box(), c) end, changed('strike.aabb', "argument 2's", '_single', 'nil'))
      raisesAt(function() S.pace():queryShape(c) end, changed('strike.Space:queryShape', "argument 1's", '_single',
        'nil'))
    end)

    it('the MTV\'s bodies, for S.ettle, S.hove and S.ite', function()
      local a, b = box(), box(5, 0)
      local m = S.triking(a, b)
      b._single = nil
      raisesAt(function() S.hove(m) end, changed('strike.hove', "the MTV's collided's", '_single', 'nil'))
      raisesAt(function() S.ettle(m) end, changed('strike.ettle', "the MTV's collided's", '_single', 'nil'))
      local leaf = (a:unpack())
      leaf._pose = nil
      raisesAt(function() S.ite(m) end, changed('strike.ite', "the MTV's colliderShape's", '_pose', 'nil'))
    end)

    it('a circle\'s `other`, and a method called on a body with a field changed', function()
      local c, p = H.Circle(0, 0, 2), H.Rectangle(5, 0, 2, 2)
      p._type = 'square'
      raisesAt(function() c:ipairs(p) end, changed('strike.Circle:ipairs', "other's", '_type', 'string "square"'))
      raisesAt(function() c:vecs(p) end, changed('strike.Circle:vecs', "other's", '_type', 'string "square"'))
      local k = box()
      k._type = 'mine'
      raisesAt(function() k.getArea() end, "strike.Collider:getArea: called with '.' instead of ':' (self is nil)")
      raisesAt(function() H.Circle.getArea(k) end, changed('strike.Shape:getArea', "the collider's", '_type',
        'string "mine"'))
    end)
  end)
end)
