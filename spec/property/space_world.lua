--- Random worlds for spec/property/space_property_spec.lua: bodies of every kind at one
--- scale and offset, the options S.pace takes (layers, masks, groups, sensors), and random
--- operations on them (transforms of bodies and of nested members, Collider:add/remove of
--- members, space:add/remove/set, setFilter). Alongside the space, a world keeps its own
--- model: the bodies in add order (ranks) with their options, and the free bodies. Nothing
--- here reads the space's state; the spec compares the space with this model.
local S = require 'strike'
local gen = require('spec.property.gen')

local floor, sqrt, cos, sin, pi, log = math.floor, math.sqrt, math.cos, math.sin, math.pi, math.log
local logRange = gen.logRange
local unpack = table.unpack or unpack -- luacheck: ignore 113 143
local ipairs, tostring, select, setmetatable, pcall = ipairs, tostring, select, setmetatable, pcall

local W = {}
W.__index = W
W.logRange = logRange

local function g(v) return ('%.17g'):format(v) end
W.g = g

-- Layer universes: most worlds use a few layers, some use 32 (the issue asks for at least 32).
local FEW = { 'default', 'player', 'wall', 'enemy' }
local MANY = { 'default' }
for i = 2, 32 do MANY[i] = 'L' .. i end

--- A new world: `rng` drives everything; `events` asks the spec to register callbacks.
function W.new(rng, index)
  local self = setmetatable({}, W)
  self.rng, self.index = rng, index
  self.space = S.pace()
  -- the world's scale (size of a body), its unit for exact (dyadic) coordinates and its centre
  self.s = logRange(rng, 1e-3, 1e4)
  self.u = 2 ^ floor(log(self.s) / log(2)) / 8
  local function offset()
    local r = rng:next()
    if r < 0.3 then return 0 end
    local m = logRange(rng, 1, 1e6) * (rng:next() < 0.5 and -1 or 1)
    return floor(m / self.u) * self.u
  end
  self.cx, self.cy = offset(), offset()
  self.layers = rng:next() < 0.25 and MANY or FEW
  self.entries = {}    -- the bodies in the space, in add order: { body, rank, layer, mask, group, sensor }
  self.entryOf = {}    -- body -> entry
  self.info = {}       -- body -> { id, kind, exact }, for every body ever made
  self.pool = {}       -- bodies not in the space and held by no collider (removed ones, removed members)
  self.nextRank, self.nextId = 0, 0
  self.pairFilter = false
  self.log = {}        -- the operations, for failure messages
  self.fail = error    -- the spec's failure (fmt, ...), with the seed and the world
  return self
end

function W:note(fmt, ...)
  self.log[#self.log + 1] = fmt:format(...)
end

--- The last operations, for a failure message.
function W:history(k)
  k = k or 12
  local from = math.max(1, #self.log - k + 1)
  local parts = {}
  for i = from, #self.log do parts[#parts + 1] = self.log[i] end
  return ('%d ops, the last: %s'):format(#self.log, table.concat(parts, '; '))
end

function W:describe(body)
  local inf = self.info[body]
  if not inf then return tostring(body) end
  local e = self.entryOf[body]
  return ('#%d(%s%s)'):format(inf.id, inf.kind, e and (' rank ' .. e.rank) or ', out')
end

function W:register(body, kind, exact)
  self.nextId = self.nextId + 1
  self.info[body] = { id = self.nextId, kind = kind, exact = exact or false }
  return body
end

-- The region the bodies live in: a square of side L about the centre.
function W:side()
  return self.s * (3 + 1.5 * sqrt(#self.entries + 1))
end

function W:randomPoint()
  local L = self:side()
  return self.cx + self.rng:range(-L / 2, L / 2), self.cy + self.rng:range(-L / 2, L / 2)
end

function W:snap(v) return floor(v / self.u + 0.5) * self.u end

---------------------------------------------------------------------------------------
-- Shapes

local function hull(rng, size)
  while true do
    local shape = gen.shape(S, rng, 'hull', 0, 0)
    local v = shape:getVertices()
    local k = size / shape:getRadius()
    for i = 1, #v do v[i] = v[i] * k end
    if rng:next() < 0.5 then
      local r = size * logRange(rng, 0.02, 0.4)
      v.radius = r
    end
    local ok, poly = pcall(S.hapes.ConvexPolygon, v)
    if ok then return poly end
  end
end

local SHAPE_KINDS = { 'rect', 'ngon', 'hull', 'ellipse', 'circle', 'edge', 'capsule', 'roundrect', 'roundhull',
  'point', 'axisrect', 'axiscircle' }

--- A random convex shape of about `size` (radius) at (x, y), and whether its coordinates
--- are exact (dyadic, unrotated: it can be placed to touch another such shape exactly).
function W:shape(x, y, size, kind)
  local rng = self.rng
  kind = kind or SHAPE_KINDS[rng:int(1, #SHAPE_KINDS)]
  local angle = rng:range(-pi, pi)
  if kind == 'axisrect' then
    local u = self.u
    local w, h = u * 2 * rng:int(2, 16), u * 2 * rng:int(2, 16)
    return S.hapes.Rectangle(self:snap(x), self:snap(y), w, h), true
  elseif kind == 'axiscircle' then
    return S.hapes.Circle(self:snap(x), self:snap(y), self.u * rng:int(2, 16)), true
  elseif kind == 'capsule' then
    local w = size * logRange(rng, 0.2, 1)
    return S.hapes.Capsule(x, y, w, w * logRange(rng, 1, 4), angle)
  elseif kind == 'roundrect' then
    local w, h = size * logRange(rng, 0.3, 1.5), size * logRange(rng, 0.3, 1.5)
    return S.hapes.Rectangle(x, y, w, h, angle, math.min(w, h) / 2 * rng:range(0.05, 0.9))
  elseif kind == 'roundhull' or kind == 'hull' then
    local poly = hull(rng, size)
    if kind == 'hull' and poly:getRounding() > 0 then poly = S.hapes.ConvexPolygon(poly:getVertices()) end
    return poly:translateTo(x, y)
  elseif kind == 'point' then
    return S.hapes.Point(x, y)
  end
  local shape = gen.shape(S, rng, kind, 0, 0)
  shape:scale(size / shape:getRadius())
  return shape:translateTo(x, y)
end

-- A star-shaped simple polygon about (x, y) (gen.starAngles), as a Concave collider.
function W:concave(x, y, size)
  local rng = self.rng
  local n = rng:int(5, 10)
  local angles = gen.starAngles(rng, n)
  local flat = {}
  for i = 1, n do
    local r = size * rng:range(0.3, 1)
    flat[2 * i - 1], flat[2 * i] = x + r * cos(angles[i]), y + r * sin(angles[i])
  end
  return S.trikers.Concave(flat)
end

-- An open chain (a floor with hills) through 3-6 points about (x, y), or a loop.
function W:chain(x, y, size)
  local rng = self.rng
  local k = rng:int(3, 6)
  if rng:next() < 0.3 then -- a loop: a convex-ish star, positive winding
    local angles = gen.starAngles(rng, k)
    local pts = {}
    for i = 1, k do
      local r = size * rng:range(0.5, 1)
      pts[2 * i - 1], pts[2 * i] = x + r * cos(angles[i]), y + r * sin(angles[i])
    end
    return S.trikers.Chain(pts, true)
  end
  local pts, step = {}, 2 * size / (k - 1)
  for i = 1, k do
    pts[2 * i - 1], pts[2 * i] = x - size + (i - 1) * step * rng:range(0.8, 1.2), y + size * rng:range(-0.4, 0.4)
  end
  return S.trikers.Chain(pts)
end

--- A new random body near (x, y) (a random point of the region by default), registered.
function W:newBody(x, y)
  local rng = self.rng
  if not x then x, y = self:randomPoint() end
  local size = self.s * logRange(rng, 0.2, 2)
  local r = rng:next()
  if r < 0.35 then
    local shape, exact = self:shape(x, y, size)
    return self:register(shape, 'shape', exact)
  elseif r < 0.55 then
    local shape, exact = self:shape(x, y, size)
    return self:register(S.trikers.Collider(shape), 'single', exact)
  elseif r < 0.85 then
    local m = {}
    for i = 1, rng:int(2, 3) do
      m[i] = self:shape(x + size * rng:range(-0.8, 0.8), y + size * rng:range(-0.8, 0.8), size * logRange(rng, 0.3, 1))
    end
    local c
    if #m == 3 and rng:next() < 0.5 then
      c = S.trikers.Collider(m[1], S.trikers.Collider(m[2], m[3])) -- nested
    else
      c = S.trikers.Collider(unpack(m))
    end
    return self:register(c, 'compound')
  elseif r < 0.93 then
    return self:register(self:concave(x, y, size), 'concave')
  end
  return self:register(self:chain(x, y, size), 'chain')
end

---------------------------------------------------------------------------------------
-- Options and the model of the space's bookkeeping

--- Random options for add or set: each key present or not (all present with `full`).
function W:randomOpts(full)
  local rng, layers = self.rng, self.layers
  local o = {}
  if full or rng:next() < 0.5 then o.layer = layers[rng:int(1, #layers)] end
  if full or rng:next() < 0.4 then
    local r = rng:next()
    local list = {}
    if r < 0.1 then
      list = false -- every layer again (strike/space/Space.lua: mask = false)
    elseif r < 0.25 then
      for i = 1, #layers do list[i] = layers[i] end -- every layer, spelled out
    elseif r > 0.25 then -- (else {}: collides with nothing)
      for i = 1, #layers do
        if rng:next() < 0.6 then list[#list + 1] = layers[i] end
      end
      if rng:next() < 0.2 and list[1] then list[#list + 1] = list[1] end -- a duplicate
    end
    o.mask = list
  end
  if full or rng:next() < 0.3 then o.group = rng:int(-2, 2) end
  if full or rng:next() < 0.2 then o.sensor = rng:next() < 0.5 end
  return o
end

local function maskSet(list)
  local set = {}
  for i = 1, #list do set[list[i]] = true end
  return set
end

local function showOpts(o)
  if not o then return 'nil' end
  local parts = {}
  if o.layer then parts[#parts + 1] = 'layer=' .. o.layer end
  if o.mask then parts[#parts + 1] = 'mask={' .. table.concat(o.mask, ',') .. '}' end
  if o.mask == false then parts[#parts + 1] = 'mask=false' end
  if o.group then parts[#parts + 1] = 'group=' .. o.group end
  if o.sensor ~= nil then parts[#parts + 1] = 'sensor=' .. tostring(o.sensor) end
  return '{' .. table.concat(parts, ' ') .. '}'
end

local function applyOpts(e, o)
  if not o then return end
  if o.layer ~= nil then e.layer = o.layer end
  if o.mask ~= nil then e.mask = o.mask and maskSet(o.mask) end
  if o.group ~= nil then e.group = o.group end
  if o.sensor ~= nil then e.sensor = o.sensor end
end

local function removeFrom(list, v)
  for i = 1, #list do
    if list[i] == v then
      table.remove(list, i)
      return true
    end
  end
  return false
end

--- space:add(body, opts) and the model's record of it: the next rank, the defaults, opts.
function W:add(body, opts)
  local e = { body = body, layer = 'default', mask = false, group = 0, sensor = false }
  if self.space:add(body, opts) ~= body then self.fail('space:add(%s) did not return the body', body) end
  applyOpts(e, opts)
  self.nextRank = self.nextRank + 1
  e.rank = self.nextRank
  self.entries[#self.entries + 1] = e
  self.entryOf[body] = e
  removeFrom(self.pool, body)
  self:note('add %s %s', self:describe(body), showOpts(opts))
  return e
end

function W:remove(body)
  if self.space:remove(body) ~= body then self.fail('space:remove(%s) did not return the body', body) end
  local e = self.entryOf[body]
  removeFrom(self.entries, e)
  self.entryOf[body] = nil
  self.pool[#self.pool + 1] = body
  self:note('remove %s', self:describe(body))
end

function W:set(body, opts)
  if self.space:set(body, opts) ~= body then self.fail('space:set(%s) did not return the body', body) end
  applyOpts(self.entryOf[body], opts)
  self:note('set %s %s', self:describe(body), showOpts(opts))
end

--- Who can collide, from the model (Box2D's rule; docs/space.md, "Who collides"): a shared
--- non-zero group decides alone, else each layer must be in the other's mask.
function W.ruleAllows(ea, eb)
  if ea.group ~= 0 and ea.group == eb.group then return ea.group > 0 end
  return (not ea.mask or ea.mask[eb.layer] == true) and (not eb.mask or eb.mask[ea.layer] == true)
end

--- The pair filter the worlds install (a before b): deliberately not symmetric, so that a
--- space calling it the wrong way round gets other answers.
function W:pairFilterValue(a, b)
  local ia, ib = self.info[a].id, self.info[b].id
  return (ia * 7 + ib * 3) % 5 ~= 0
end

---------------------------------------------------------------------------------------
-- Operations

--- The first leaf of a body (itself for a shape; nil for an empty collider).
function W.firstLeaf(body)
  if not body.getShapeCount then return body end
  local iter, state = body:elems()
  return iter(state, nil)
end

function W:randomEntry()
  local n = #self.entries
  if n == 0 then return nil end
  return self.entries[self.rng:int(1, n)]
end

-- An entry whose body is a collider that takes member operations (not a Concave or Chain).
function W:mutableEntry()
  local list = {}
  for _, e in ipairs(self.entries) do
    local k = self.info[e.body].kind
    if k == 'single' or k == 'compound' then list[#list + 1] = e end
  end
  if #list == 0 then return nil end
  return list[self.rng:int(1, #list)]
end

-- A random shape or collider nested in the collider c (not c itself), and its path.
local function member(rng, c)
  local node, depth = c, 0
  repeat
    local kids = { node:unpack() }
    if #kids == 0 then return nil end
    node = kids[rng:int(1, #kids)]
    depth = depth + 1
  until node.getShapeCount == nil or rng:next() < 0.5
  return node, depth
end

-- A random transform of `obj` (a body or a member): translate, rotate (about its centroid
-- or a point), scale, translateTo or rotateTo. Returns a description.
function W:transform(obj)
  local rng, s = self.rng, self.s
  local r = rng:next()
  if r < 0.04 then -- far away (and back with a later translateTo)
    local d = self:side() * logRange(rng, 10, 1e4)
    local a = rng:range(-pi, pi)
    obj:translate(d * cos(a), d * sin(a))
    return 'translate far'
  elseif r < 0.45 then
    local d = s * logRange(rng, 0.01, 4)
    local a = rng:range(-pi, pi)
    obj:translate(d * cos(a), d * sin(a))
    return 'translate'
  elseif r < 0.55 then
    local x, y = self:randomPoint()
    obj:translateTo(x, y)
    return 'translateTo'
  elseif r < 0.75 then
    if rng:next() < 0.5 then
      obj:rotate(rng:range(-pi, pi))
    else
      local cx, cy = obj:getCentroid()
      obj:rotate(rng:range(-0.5, 0.5), cx + s * rng:range(-2, 2), cy + s * rng:range(-2, 2))
    end
    return 'rotate'
  elseif r < 0.8 then
    obj:rotateTo(rng:range(-pi, pi))
    return 'rotateTo'
  end
  -- keep sizes within [0.1, 10] of the world's scale
  local R = obj:getRadius()
  local sf = rng:range(0.7, 1.4)
  if R > 0 and (R * sf > 10 * self.s or R * sf < 0.05 * self.s) then sf = 1 / sf end
  obj:scale(sf)
  return 'scale ' .. g(sf)
end

-- Place the exact body b so that it touches the exact body a: side by side (their bounds
-- share a side, with some overlap along it), by a dyadic translation (so, exactly).
function W:touch(a, b)
  local rng = self.rng
  local ax0, ay0, ax1, ay1 = a:getBounds()
  local bx0, by0, bx1, by1 = b:getBounds()
  local side = rng:int(1, 4)
  local dx, dy
  local function along(lo0, hi0, lo1, hi1)
    -- a shift of [lo1, hi1] so that it overlaps [lo0, hi0]: its low end in (lo0 - w1, hi0)
    local w1 = hi1 - lo1
    local k0, k1 = math.ceil((lo0 - w1) / self.u) + 1, floor(hi0 / self.u) - 1
    if k1 < k0 then k1 = k0 end
    return rng:int(k0, k1) * self.u - lo1
  end
  if side == 1 then dx, dy = ax1 - bx0, along(ay0, ay1, by0, by1)
  elseif side == 2 then dx, dy = ax0 - bx1, along(ay0, ay1, by0, by1)
  elseif side == 3 then dx, dy = along(ax0, ax1, bx0, bx1), ay1 - by0
  else dx, dy = along(ax0, ax1, bx0, bx1), ay0 - by1 end
  b:translate(dx, dy)
end

--- One random operation on the world; returns its name.
function W:step(ops)
  local rng = self.rng
  local r = rng:next()
  local e = self:randomEntry()
  if r < 0.25 and #self.pool > 0 and rng:next() < 0.1 then -- a body out of the space: nothing to notice
    local body = self.pool[rng:int(1, #self.pool)]
    local what = self:transform(body)
    self.info[body].exact = false
    self:note('%s %s', what, self:describe(body))
    return 'transform out'
  elseif r < 0.25 and e then
    local what = self:transform(e.body)
    self.info[e.body].exact = false
    self:note('%s %s', what, self:describe(e.body))
    return 'transform'
  elseif r < 0.35 then -- a nested member of a body in the space
    local m = self:mutableEntry()
    if not m then return 'none' end
    local obj, depth = member(rng, m.body)
    if not obj then return 'none' end
    local what = self:transform(obj)
    self.info[m.body].exact = false
    self:note('%s a member (depth %d) of %s', what, depth, self:describe(m.body))
    return 'member'
  elseif r < 0.42 then -- Collider:add: a new shape, or a free bare shape from the pool
    local m = self:mutableEntry()
    if not m then return 'none' end
    local child
    for i = 1, #self.pool do
      local p = self.pool[i]
      if self.info[p].kind == 'shape' and rng:next() < 0.3 then child = p; break end
    end
    if child then
      removeFrom(self.pool, child)
      self.info[child].kind = 'member of #' .. self.info[m.body].id -- (now part of a body)
    else
      local x, y = m.body:getCentroid()
      if m.body:getShapeCount() == 0 then x, y = self:randomPoint() end
      child = self:shape(x + self.s * rng:range(-1, 1), y + self.s * rng:range(-1, 1), self.s * logRange(rng, 0.2, 1))
    end
    m.body:add(child)
    self.info[m.body].exact = false
    self.info[m.body].kind = 'compound'
    self:note('Collider:add to %s', self:describe(m.body))
    return 'memberAdd'
  elseif r < 0.48 then -- Collider:remove: a member becomes a free body
    local m = self:mutableEntry()
    if not m then return 'none' end
    local count = select('#', m.body:unpack())
    if count == 0 or (count == 1 and rng:next() < 0.7) then return 'none' end
    local child = m.body:remove(rng:int(1, count))
    self:register(child, child.getShapeCount and 'compound' or 'shape')
    self.pool[#self.pool + 1] = child
    self.info[m.body].exact = false
    self:note('Collider:remove from %s (%d left)', self:describe(m.body), count - 1)
    return 'memberRemove'
  elseif r < 0.62 then -- space:add: a new body, a free one, or a copy of one in the space
    local body
    local q = rng:next()
    if q < 0.3 and #self.pool > 0 then
      body = self.pool[rng:int(1, #self.pool)]
    elseif q < 0.4 and e then
      body = e.body:copy()
      local inf = self.info[e.body]
      self:register(body, inf.kind == 'single' and 'single' or inf.kind, inf.exact)
    else
      body = self:newBody()
    end
    local opts
    if rng:next() < 0.7 then opts = self:randomOpts() end
    self:add(body, opts)
    return 'add'
  elseif r < 0.72 and e then
    self:remove(e.body)
    return 'remove'
  elseif r < 0.84 and e then
    self:set(e.body, self:randomOpts())
    return 'set'
  elseif r < 0.87 then
    if self.pairFilter then
      self.space:setFilter(nil)
      self.pairFilter = false
      self:note('setFilter(nil)')
    else
      self.space:setFilter(ops.pairFilter)
      self.pairFilter = true
      self:note('setFilter(fn)')
    end
    return 'filter'
  elseif r < 0.97 then -- exact touching: an exact body placed against another exact one
    local list = {}
    for _, x in ipairs(self.entries) do
      if self.info[x.body].exact then list[#list + 1] = x.body end
    end
    if #list < 2 then
      local body = self:register(S.hapes.Rectangle(self:snap(self.cx), self:snap(self.cy), 4 * self.u, 6 * self.u),
        'shape', true)
      self:add(body, rng:next() < 0.5 and self:randomOpts() or nil)
      return 'add'
    end
    local i = rng:int(1, #list)
    local j = rng:int(1, #list - 1)
    if j >= i then j = j + 1 end
    self:touch(list[i], list[j])
    self:note('touch %s against %s', self:describe(list[j]), self:describe(list[i]))
    return 'touch'
  elseif e then -- errors that must change nothing
    local ok = pcall(S.trikers.Collider().add, S.trikers.Collider(), e.body)
    if ok then self.fail('Collider:add accepted a body that is in a space: %s', e.body) end
    ok = pcall(self.space.add, self.space, e.body)
    if ok then self.fail('space:add accepted a body already in it: %s', e.body) end
    local m = self:mutableEntry()
    if m and m.body:getShapeCount() > 0 then -- (a leaf of a body in the space)
      local leaf = W.firstLeaf(m.body)
      ok = pcall(self.space.add, self.space, leaf)
      if ok then self.fail('space:add accepted a shape held by a collider (a leaf of %s)', m.body) end
    end
    self:note('error cases on %s', self:describe(e.body))
    return 'errors'
  end
  return 'none'
end

--- Fill the world with n new bodies (random options on some).
function W:populate(n)
  for _ = 1, n do
    local body = self:newBody()
    self:add(body, self.rng:next() < 0.6 and self:randomOpts() or nil)
  end
end

return W
