-- The shape data contract (strike/base/layout.lua): a shape keeps its scalars and its
-- world-space data in numbered slots, and only a few named fields, so that its hash part
-- stays small (on LuaJIT a power of two of 24-byte nodes: 8 nodes for a shape, where two
-- dozen named scalars took 32). Checked on every built-in shape kind, after the uses that
-- write its caches: construction, a collider, transforms, tests, rays, a space.
local S = require('strike')
local layout = require('strike.base.layout')

local H, T = S.hapes, S.trikers

-- The named fields strike's shapes may have: their own, the collider's link and a space's.
-- Every one starts with `_`: the other names are the game's (README, "Your data on bodies";
-- spec/game_fields_spec.lua).
local COMMON = { _pose = true, _l = true, _seams = true, _kind = true, _parent = true, _space = true, _sid = true }
-- Each class's own data (what its unpack needs): none, now that it is kept in the local
-- geometry (`_l`, strike/base/VertexShape.lua) or in the slots (a circle's radius).
local OWN = {}

local function namedKeys(s)
  local keys = {}
  for k in pairs(s) do
    if type(k) ~= 'number' then keys[#keys + 1] = tostring(k) end
  end
  table.sort(keys)
  return keys
end

-- Use a shape the ways that fill its caches, inside a collider and in a space, and bare.
local function exercise(shape, body)
  local space = S.pace()
  space:add(body)
  local probe = T.Rectangle(0, 0, 30, 30)
  for _ = 1, 3 do
    body:translate(1.5, -0.5)
    body:getBounds()
    S.triking(body, probe, S.MTV())
    space:collisions({})
  end
  body:rotate(0.3)
  body:scale(1.5)
  body:getRadius()
  body:getArea()
  S.triking(body, probe, S.MTV())
  body:rayCast(-100, 0, 1, 0)
  space:rayCast(-100, 0, 1, 0)
  space:collisions({})
  return shape
end

local function cases()
  local list = {
    { 'Rectangle', function() return H.Rectangle(0, 0, 10, 20) end },
    { 'Rectangle', function() return H.Rectangle(0, 0, 10, 20, 0.2, 3) end }, -- rounded
    { 'RegularPolygon', function() return H.RegularPolygon(0, 0, 6, 10) end },
    { 'ConvexPolygon', function() return H.ConvexPolygon(0, 0, 10, 0, 12, 8, 5, 12, -2, 6) end },
    { 'Ellipse', function() return H.Ellipse(0, 0, 10, 5) end },
    { 'Edge', function() return H.Edge(0, 0, 10, 4) end },
    { 'Capsule', function() return H.Capsule(0, 0, 6, 20) end },
    { 'Circle', function() return H.Circle(0, 0, 5) end },
    { 'Point', function() return H.Point(1, 1) end },
  }
  return list
end

-- Call fn(name, shape, where) with every case, built and used bare and in a collider.
local function eachUsedShape(fn)
  for _, c in ipairs(cases()) do
    for _, inCollider in ipairs({ false, true }) do
      local s = c[2]()
      exercise(s, inCollider and T.Collider(s) or s)
      fn(c[1], s, inCollider and 'in a collider' or 'bare')
    end
  end
end

describe('the shape data contract (layout.lua)', function()
  it('every header slot is set, and the array part ends at the shape\'s last slot', function()
    eachUsedShape(function(name, s)
      local count = s[layout.COUNT]
      local size = count and layout.size(count) or layout.SHAPE_HEADER
      for k = 1, size do
        assert.is_not_nil(s[k], ('%s: slot %d of %d'):format(name, k, size))
      end
      assert.is_nil(s[size + 1], name .. ': a slot past the last')
      assert.equals(size, #s, name)
      assert.is_boolean(s[layout.DIRTY], name)
      if name == 'Circle' or name == 'Point' then
        assert.is_nil(count, name .. ' has no vertex count')
      else
        assert.is_number(count, name)
      end
    end)
  end)

  it('a shape has no named fields beyond the documented few (4 in a collider, 5 bare in a space)', function()
    -- (_pose, _kind, _l but for a circle, then _parent, or a space's _space and _sid: a
    -- collider's shape fits LuaJIT's 4-node hash, a body's the 8-node one)
    eachUsedShape(function(name, s, where)
      local keys = namedKeys(s)
      local own = OWN[name] or {}
      for _, k in ipairs(keys) do
        assert.is_true(COMMON[k] or own[k] or false,
          ('%s (%s) has the named field %s: strike\'s scalars belong in layout.lua\'s slots'):format(name, where, k))
      end
      local most = where == 'in a collider' and 4 or 5
      assert.is_true(#keys <= most, ('%s (%s) has %d named fields: %s'):format(name, where, #keys,
        table.concat(keys, ' ')))
    end)
  end)

  it('a single-shape collider\'s shape has room for 4 named fields, and needs no more', function()
    -- (Shape._forCollider: its table is made with a 4-node hash; spec/body_memory_spec.lua
    -- counts the bytes)
    for _, make in ipairs({
      function() return T.Rectangle(0, 0, 10, 20) end, function() return T.Rectangle(0, 0, 10, 20, 0.2, 3) end,
      function() return T.RegularPolygon(0, 0, 6, 10) end, function() return T.Ellipse(0, 0, 10, 5) end,
      function() return T.Circle(0, 0, 5) end, function() return T.Capsule(0, 0, 6, 20) end,
    }) do
      local c = make()
      local s = exercise(c:unpack(), c)
      local keys = namedKeys(s)
      assert.is_true(#keys <= 4, table.concat(keys, ' '))
    end
  end)

  it('a chain segment keeps its neighbours\' data in slots too, after its vertex records', function()
    local chain = T.Chain(0, 0, 10, 0, 20, 5, 30, 5)
    exercise((chain:unpack()), chain)
    for _, seg in ipairs({ chain:unpack() }) do
      local keys = namedKeys(seg)
      for _, k in ipairs(keys) do
        assert.is_true(COMMON[k] or false, 'ChainSegment has the named field ' .. k)
      end
      assert.is_true(#keys <= 8, ('ChainSegment has %d named fields'):format(#keys))
      assert.equals(layout.CHAIN_SIZE, #seg)
    end
  end)

  it('copies keep the layout', function()
    local link = { _parent = true, _space = true, _sid = true } -- (a copy is in no collider and no space)
    local function ownKeys(t)
      local keys = {}
      for _, k in ipairs(namedKeys(t)) do
        if not link[k] then keys[#keys + 1] = k end
      end
      return keys
    end
    for _, c in ipairs(cases()) do
      local s = c[2]()
      exercise(s, T.Collider(s))
      local copy = s:copy(5, 5, 1)
      assert.equals(#s, #copy, c[1])
      assert.same(ownKeys(s), ownKeys(copy), c[1])
    end
  end)
end)
