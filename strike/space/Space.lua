--- S.pace: a world of bodies (colliders and bare shapes) with a broadphase, exact queries,
--- layers and contact events.
---
--- How it keeps up without update calls: a body in a space carries `_space` (the space) and
--- `_sid` (its proxy id in the broadphase). Every move of a shape ends in Shape:_touch, and
--- every change of a collider's members in its invalidate; both walk up to the root body
--- and, when it is in a space, queue its id (Space:_moved), once until the next query. A
--- query first refreshes the queued bodies' bounds in the broadphase (strike/space/tree.lua,
--- a dynamic AABB tree whose fat boxes absorb small moves), so bodies that do not move cost
--- nothing.
---
--- Order. A body's rank is the order in which it was added (a body removed and added again
--- gets a new rank). Every list is in rank order; pairs by (rank of a, rank of b), a added
--- before b; rayCastAll by distance, then rank.
---
--- Per-body data lives in arrays indexed by proxy id (the tree reuses the last freed id):
--- the body, its rank, layer, mask, group, sensor flag and whether it is queued.
local ROOT = (...):match('^(.-)%.space%.[^%.]+$')
local Object = require(ROOT .. '.class')
local Tree = require(ROOT .. '.space.tree')
local filter = require(ROOT .. '.space.filter')
local compound = require(ROOT .. '.collide.compound')
local MTV = require(ROOT .. '.collide.MTV')
local args = require(ROOT .. '.collide.args')
local check = require(ROOT .. '.check')
local limits = require(ROOT .. '.limits')
local layout = require(ROOT .. '.base.layout')
local Rectangle = require(ROOT .. '.shapes.Rectangle')
local ray = require(ROOT .. '.collide.ray')
local Collider = require(ROOT .. '.colliders.Collider')
local reserved = require(ROOT .. '.reserved')
local spaces = require(ROOT .. '.base.Shape')._spaces
local boundsOnly = require(ROOT .. '.base.VertexShape')._boundsOnly

local collide = compound.collide
local fail, describe, what, badSelf = check.fail, check.describe, check.what, check.badSelf
local finite = check.finite
local pairRule, queryFilter, checkQuery = filter.pair, filter.query, filter.checkQuery
local sqrt, huge, abs, type = math.sqrt, math.huge, math.abs, type
local X, Y = layout.X, layout.Y
local DIRTY, AREA, RADIUS = layout.DIRTY, layout.AREA, layout.RADIUS
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY

-- Pair keys and sort keys pack two numbers below 2^26 into one double.
local K = 67108864

---@class strike.Space : strike.Object
local Space = Object:extend()
Space.type = 'space'
Space._type = 'space' -- (the class marker strike reads: strike/reserved.lua)
Space.name = 'Space'

--- S.ite, set by strike/init.lua (the contacts of a record).
Space._ite = nil

--- A new, empty space.
function Space:new()
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Space:new') end
  self._tree = Tree.new()
  self._body, self._rank, self._layer, self._mask, self._group, self._sensor = {}, {}, {}, {}, {}, {}
  self._queued, self._queue, self._nq = {}, {}, 0
  self._n, self._nextRank = 0, 0
  self._buf = {}
  -- the queries' scratch, one level per query in progress (a filter may query the space:
  -- see enter)
  self._depth, self._levels = 0, {}
  -- the broadphase's version: it changes with every body added, removed or moved, but for
  -- the body a move is moving (_mover, its id; 0 when none), so that a move can keep its
  -- candidates while only it moves (strike/space/motion.lua)
  self._version, self._mover = 0, 0
  -- the number of removals so far: a call whose game code (a filter, a callback) removed
  -- bodies sees it change, and drops them from its results (see dropRemoved); and, by body,
  -- the number its last removal from this space made (weak: it keeps no body alive)
  self._removals = 0
  self._gone = setmetatable({}, { __mode = 'k' })
  -- true while a call that runs game code is in progress at the top (see protect)
  self._guard = false
  -- contact tracking: records by pair key, the touching records of the last call (in
  -- order) and of this one, and a pool of ended records
  self._active, self._prev, self._cur, self._pool, self._ended = {}, {}, {}, {}, {}
  self._nprev, self._frame = 0, 0
  -- the records this call of collisions() made (undone when its pair filter raises)
  self._fresh, self._nfresh = {}, 0
  self._inCollisions = false
  -- the events of the last collisions() still to run (see emitEvents): event _emE (0: none)
  -- of _emN (the first _emNe end the pairs in _ended, the others are _prev's), from its
  -- callback _emC, of kind _emKind, whose list had _emCount callbacks when it started;
  -- _emR is the number of removals when they started
  self._emE, self._emC, self._emN, self._emNe, self._emKind, self._emCount, self._emR = 0, 1, 0, 0, 'end', 0, 0
  self._scratch = MTV()
  self._on = { begin = {}, stay = {}, ['end'] = {} }
  self._listeners = 0
  self._compact = false -- (a callback was removed while events were running: see off)
  self._pairFilter = false
end

-- A query begins: its scratch is the level for the depth it runs at, made on first use.
-- A query started from a filter of another one (or from a callback) runs one level deeper,
-- so neither sees the other's candidates, ray or rectangle. Each query leaves with
-- leave(self, level), which puts the depth back to the level's own: a query that a game's
-- filter ran, and whose error the filter caught, leaves its level taken, and the query
-- that ran the filter then gives it back. A call at the top that runs game code is
-- protected (protect): an error leaves every level free.
local function enter(self)
  local d = self._depth + 1
  self._depth = d
  local level = self._levels[d]
  if not level then
    level = {
      index = d,
      ids = {}, ts = {}, stack = {}, tstack = {}, -- candidates, their entry distances, the tree walk's
      probe = false, -- the rectangle of queryRect, made on first use
      -- rayCast's ray and best hit so far (see rayVisit)
      x = 0, y = 0, dx = 0, dy = 0, filter = false, hit = false, rank = 0, d = 0, hx = 0, hy = 0, nx = 0, ny = 0,
      shape = false,
      -- the verdicts of a filter function, by proxy id, for the query with this stamp
      -- (valid while the id holds a body of the rank noted: see verdict)
      stamp = 0, vstamp = {}, vrank = {}, vok = {},
      -- the removals and the tree's version when rayCast's walk started; its second pass's hits
      removals = 0, version = 0, hits = false,
      space = self, -- (the ray's visitor gets the level alone)
    }
    self._levels[d] = level
  end
  return level
end

local function leave(self, level) self._depth = level.index - 1 end

-- What a call that a game's code interrupted with an error leaves behind, undone: every
-- level free and holding nothing of the game's, no move under way, no body marked as met.
-- Run at the end of every protected call at the top, whether it raised or not: a call it
-- ran from a filter may have raised an error that the filter caught.
local function recover(self)
  self._depth, self._mover = 0, 0
  local levels = self._levels
  for d = 1, #levels do
    local level = levels[d]
    level.filter, level.hit, level.shape, level.body, level.sid = false, false, false, false, false
    -- the hits a rayCast or a move's leg had found when an error stopped it (a finished one
    -- leaves them false), its one-leaf lists and its step's probe
    local hits = level.hits
    if hits and hits[1] then
      for h = 1, #hits do hits[h] = false end
    end
    local one1, one2, probe = level.one1, level.one2, level.stepHit
    if one1 then one1[1], one2[1] = nil, nil end
    if probe then probe.body, probe.pick = nil, nil end
  end
  local lists = rawget(self, '_cols')
  if lists then
    for d = 1, #levels do
      local cols = lists[d] -- (none for a level no move ran at)
      if cols then
        local visited = cols.visited
        for i = 1, #cols do
          local other = cols[i].other
          if other then visited[other] = nil end
        end
        cols.hit.body, cols.hit.pick = nil, nil
      end
    end
  end
end

local function finish(self, ok, ...)
  self._guard = false
  recover(self)
  if not ok then error((...), 0) end
  return ...
end

-- Run fn(self, ...) and return what it returns; when it raises an error (a game's filter
-- or callback did, or strike found a game's value wrong), undo what the call left half done
-- (recover; run after a call that returned too) and raise the same error again. Used by the
-- calls at the top that may run the game's code, only then (pcall costs a little); calls
-- those run are protected by it.
local function protect(self, fn, ...)
  self._guard = true
  return finish(self, pcall(fn, self, ...))
end

-- The filter's verdict on body b (proxy id) for the query of `level`: asked once per body
-- and query, kept in the level (a query that walks again after the game's code changed the
-- tree asks no filter twice).
local function verdict(self, level, f, b, id)
  local rank = self._rank[id]
  if level.vstamp[id] == level.stamp and level.vrank[id] == rank then return level.vok[id] end
  local ok = f(b) and true or false
  level.vstamp[id], level.vrank[id], level.vok[id] = level.stamp, rank, ok
  return ok
end

local function isSpace(v) return type(v) == 'table' and v._tree ~= nil and getmetatable(v) ~= nil end

local function checkOut(fname, out, i)
  if out ~= nil and (type(out) ~= 'table' or out._type ~= nil) then
    fail(('%s: argument %d (out) must be a table for the results (a previous result, or {}), got %s')
      :format(fname, i, what(out)))
  end
end

local function isBody(v)
  return type(v) == 'table' and getmetatable(v) ~= nil and (v._type == 'shape' and args.isShape(v)
    or v._type == 'collider' and args.isCollider(v))
end

local function checkBody(fname, v, i)
  if not isBody(v) then args.badBody(fname, i, v) end
end

-- The failure path of idOf, ownId and _moved: `body` (`owner` in the message) is not where
-- its `_space` and `_sid` say. When the space holds it after all, the game changed one of
-- them; when they name no space, or a body of theirs was changed, that is the error
-- (strike/reserved.lua); else it is not in this space.
local function notHere(self, fname, body, owner)
  for _, b in pairs(self._body) do
    if b == body then
      local s = rawget(body, '_space')
      if s ~= self then reserved.fail(fname, owner, body, body, '_space', s) end
      reserved.fail(fname, owner, body, body, '_sid', rawget(body, '_sid'))
    end
  end
  reserved.check(fname, owner, body)
  fail(('%s: %s (%s) is not in this space'):format(fname, owner, what(body)))
end

-- The proxy id of a body in this space, or an error.
local function idOf(self, fname, body)
  checkBody(fname, body, 1)
  local id = body._sid
  if rawget(body, '_space') ~= self or self._body[id] ~= body then notHere(self, fname, body, 'argument 1') end
  return id
end

-- The proxy id of a body (argument 1 of `fname`) when it is in this space, else false; a
-- `_space` or `_sid` that is not as this space left them is an error naming it.
local function ownId(self, fname, body)
  local s = rawget(body, '_space')
  if s == self then
    local id = body._sid
    if self._body[id] ~= body then notHere(self, fname, body, 'argument 1') end
    return id
  end
  local id = rawget(body, '_sid')
  if (s and not spaces[s]) or (id ~= nil and self._body[id] == body) then notHere(self, fname, body, 'argument 1') end
  return false
end

------------------------------------------------------------------ moves

--- Queue a body that moved (called by Shape:_touch and Collider's invalidate on the root).
---@param body strike.Shape|strike.Collider
function Space:_moved(body)
  local id = body._sid
  if self._body[id] ~= body then notHere(self, 'strike', body, 'a body') end -- (a `_sid` the game changed)
  local queued = self._queued
  if not queued[id] then
    queued[id] = true
    if id ~= self._mover then self._version = self._version + 1 end
    local n = self._nq + 1
    self._nq = n
    self._queue[n] = id
  end
end

-- Bring the broadphase up to date with the bodies that moved.
local function flush(self)
  local nq = self._nq
  if nq == 0 then return end
  local queue, queued, body, tree = self._queue, self._queued, self._body, self._tree
  local place = tree.place
  for i = 1, nq do
    local id = queue[i]
    if queued[id] then
      queued[id] = false
      local b = body[id]
      if b._pose then -- a shape: its bounds without the getter's checks
        local x0, y0, x1, y1
        if b[DIRTY] then
          -- (a polygon that only moved: its last bounds, moved; its vertices wait for the
          -- narrow phase, which refreshes only the shapes in a pair whose boxes meet; and so
          -- do those of a polygon never refreshed: boundsOnly)
          local movedBounds = b._movedBounds
          if movedBounds then x0, y0, x1, y1 = movedBounds(b) end
          if not x0 then boundsOnly(b) end
        end
        if x0 then place(tree, id, x0, y0, x1, y1) else place(tree, id, b[MINX], b[MINY], b[MAXX], b[MAXY]) end
      else
        place(tree, id, b:getBounds())
      end
    end
  end
  self._nq = 0
end

------------------------------------------------------------------ bodies

local OPTIONS = { layer = true, mask = true, group = true, sensor = true }

-- Validate an options table; returns layer, mask, group, sensor, each nil when not given
-- (mask: a set, or false for `mask = false`: every layer).
local function options(fname, opts)
  if opts == nil then return nil, nil, nil, nil end
  if type(opts) ~= 'table' then
    fail(('%s: argument 2 (options) must be a table such as {layer = \'wall\'}, got %s'):format(fname, what(opts)))
  end
  if getmetatable(opts) ~= nil then
    local w = what(opts)
    fail(('%s: argument 2 (options) must be a plain table such as {layer = \'wall\'}, got %s')
      :format(fname, w == 'table' and 'a table with a metatable' or w))
  end
  local unknown = check.unknownKey(opts, OPTIONS)
  if unknown ~= nil then
    fail(('%s: unknown option %s (options are layer, mask, group and sensor)'):format(fname, describe(unknown)))
  end
  local layer, mask, group, sensor = opts.layer, opts.mask, opts.group, opts.sensor
  if layer ~= nil and type(layer) ~= 'string' then
    fail(('%s: layer must be a layer name (a string), got %s'):format(fname, describe(layer)))
  end
  if mask ~= nil and mask ~= false then mask = filter.maskSet(mask, fname) end
  if group ~= nil and (type(group) ~= 'number' or group % 1 ~= 0 or not finite(group)) then
    fail(('%s: group must be an integer (0: none; negative: never collide; positive: always), got %s')
      :format(fname, describe(group)))
  end
  if sensor ~= nil and type(sensor) ~= 'boolean' then
    fail(('%s: sensor must be a boolean, got %s'):format(fname, describe(sensor)))
  end
  return layer, mask, group, sensor
end

-- Give every body a new rank 1..n in its rank order (when ranks would pass K).
local function renumber(self)
  local rank, keys, n = self._rank, {}, 0
  for id = 1, self._tree.idTop do
    if self._body[id] then
      n = n + 1
      keys[n] = rank[id] * K + id
    end
  end
  table.sort(keys)
  for i = 1, n do rank[keys[i] % K] = i end
  self._nextRank = n
end

--- Add a body: a collider, or a shape that no collider holds. Options: `layer` (a name;
--- default 'default'), `mask` (a list of layer names it collides with; default, or false:
--- every layer), `group` (an integer: bodies sharing a negative group never collide, a positive
--- one always), `sensor` (true: reports events, never an MTV).
---@param body strike.Collider|strike.Shape
---@param opts table|nil
---@return strike.Collider|strike.Shape body
function Space:add(body, opts)
  if not isSpace(self) then badSelf(self, 'strike.Space:add') end
  checkBody('strike.Space:add', body, 1)
  local other = rawget(body, '_space')
  if body._parent or other or rawget(body, '_sid') ~= nil then
    -- (a `_parent`, `_space` or `_sid` the game set is an error naming it)
    if other == self then ownId(self, 'strike.Space:add', body) end
    reserved.check('strike.Space:add', 'argument 1', body)
  end
  if body._parent then
    fail(('strike.Space:add: argument 1 (%s) is held by a collider; add the outermost collider instead')
      :format(what(body)))
  end
  if other == self then fail('strike.Space:add: argument 1 is already in this space') end
  if other then fail('strike.Space:add: argument 1 is in another space; remove it from that one first') end
  local layer, mask, group, sensor = options('strike.Space:add', opts)
  local id
  if body._pose and body[DIRTY] then -- (a shape: its bounds alone, as flush takes them)
    boundsOnly(body)
    id = self._tree:insert(body[MINX], body[MINY], body[MAXX], body[MAXY])
  else
    id = self._tree:insert(body:getBounds()) -- (a collider's bounds take its leaves' alone too)
  end
  self._version = self._version + 1
  if self._nextRank >= K - 1 then renumber(self) end
  local r = self._nextRank + 1
  self._nextRank = r
  self._body[id], self._rank[id] = body, r
  self._layer[id], self._mask[id] = layer or filter.DEFAULT, mask or false -- (false: every layer)
  self._group[id], self._sensor[id] = group or 0, sensor or false
  self._queued[id] = false
  body._space, body._sid = self, id
  spaces[self] = Space._moved -- (the spaces bodies are in: see Shape:_touch)
  self._n = self._n + 1
  return body
end

--- Change a body's options (the keys given; the others stay): see Space:add.
---@param body strike.Collider|strike.Shape
---@param opts table
---@return strike.Collider|strike.Shape body
function Space:set(body, opts)
  if not isSpace(self) then badSelf(self, 'strike.Space:set') end
  local id = idOf(self, 'strike.Space:set', body)
  if opts == nil then
    fail('strike.Space:set: argument 2 (options) must be a table such as {layer = \'wall\'}, got nil')
  end
  local layer, mask, group, sensor = options('strike.Space:set', opts)
  if layer ~= nil then self._layer[id] = layer end
  if mask ~= nil then self._mask[id] = mask end
  if group ~= nil then self._group[id] = group end
  if sensor ~= nil then self._sensor[id] = sensor end
  return body
end

--- A body's options: layer, mask (a new list of names, sorted; nil for every layer), group
--- and whether it is a sensor.
---@param body strike.Collider|strike.Shape
---@return string layer
---@return string[]|nil mask
---@return integer group
---@return boolean sensor
function Space:get(body)
  if not isSpace(self) then badSelf(self, 'strike.Space:get') end
  local id = idOf(self, 'strike.Space:get', body)
  local set, mask = self._mask[id], nil
  if set then
    mask = {}
    for name in pairs(set) do mask[#mask + 1] = name end
    table.sort(mask)
  end
  return self._layer[id], mask, self._group[id], self._sensor[id]
end

--- Remove a body. Its touching pairs end at the next collisions() (the 'end' events run then).
---@param body strike.Collider|strike.Shape
---@return strike.Collider|strike.Shape body
function Space:remove(body)
  if not isSpace(self) then badSelf(self, 'strike.Space:remove') end
  local id = idOf(self, 'strike.Space:remove', body)
  self._tree:remove(id)
  self._version = self._version + 1
  self._body[id], self._rank[id], self._layer[id], self._mask[id] = false, false, false, false
  self._group[id], self._sensor[id], self._queued[id] = false, false, false
  body._space, body._sid = false, nil
  self._n = self._n - 1
  local removals = self._removals + 1
  self._removals, self._gone[body] = removals, removals
  return body
end

--- Whether the body is in this space.
---@param body any
---@return boolean
function Space:has(body)
  if not isSpace(self) then badSelf(self, 'strike.Space:has') end
  if type(body) ~= 'table' then return false end
  local here = rawget(body, '_space') == self and self._body[body._sid] == body
  -- (a body whose `_space` or `_sid` the game changed: an error naming it)
  if not here and reserved.classType(body) then ownId(self, 'strike.Space:has', body) end
  return here
end

--- The number of bodies.
---@return integer
function Space:count()
  if not isSpace(self) then badSelf(self, 'strike.Space:count') end
  return self._n
end

-- Sort ids[1..k] by rank (keys rank * K + id, sorted as numbers: no comparator, no garbage).
local function byRank(self, ids, k)
  local rank = self._rank
  for i = 1, k do
    local id = ids[i]
    ids[i] = rank[id] * K + id
  end
  table.sort(ids)
  for i = 1, k do ids[i] = ids[i] % K end
end

-- Clear list[k + 1 ...] (an `out` table may hold anything: past a hole too, when the
-- length operator still sees it).
local function trim(list, k)
  local i = k + 1
  while list[i] ~= nil do
    list[i] = nil
    i = i + 1
  end
  if #list > k then
    for key in pairs(list) do
      if type(key) == 'number' and key > k then list[key] = nil end
    end
  end
end

--- Every body, in the order they were added (into `out` when given).
---@param out table|nil
---@return table list
---@return integer n
function Space:bodies(out)
  if not isSpace(self) then badSelf(self, 'strike.Space:bodies') end
  checkOut('strike.Space:bodies', out, 1)
  out = out or {}
  -- (the ids are sorted in a list of the space's own: whatever `out` held is overwritten,
  -- never sorted or read)
  local ids = rawget(self, '_bodyIds')
  if not ids then
    ids = {}
    self._bodyIds = ids
  end
  local body, k = self._body, 0
  for id = 1, self._tree.idTop do
    if body[id] then
      k = k + 1
      ids[k] = id
    end
  end
  trim(ids, k)
  byRank(self, ids, k)
  for i = 1, k do out[i] = body[ids[i]] end
  trim(out, k)
  return out, k
end

------------------------------------------------------------------ pair rule

--- Set the pair filter: `fn(a, b)` (a added before b) returns true when the pair may
--- collide; nil removes it. Runs after layers, masks and groups allow the pair.
---@param fn function|nil
function Space:setFilter(fn)
  if not isSpace(self) then badSelf(self, 'strike.Space:setFilter') end
  if fn ~= nil and type(fn) ~= 'function' then
    fail(('strike.Space:setFilter: argument 1 must be a function (a, b) -> boolean or nil, got %s'):format(what(fn)))
  end
  self._pairFilter = fn or false
end

-- May proxies i and j (rank i < rank j) collide?
local function allowed(self, i, j)
  local layer, mask, group = self._layer, self._mask, self._group
  if not pairRule(layer[i], mask[i], group[i], layer[j], mask[j], group[j]) then return false end
  local pf = self._pairFilter
  return not pf or pf(self._body[i], self._body[j]) and true or false
end

------------------------------------------------------------------ events

local EVENTS = { begin = true, stay = true, ['end'] = true }

local function checkEvent(fname, event)
  if not EVENTS[event] then
    fail(("%s: argument 1 must be 'begin', 'stay' or 'end', got %s"):format(fname, describe(event)))
  end
end

--- Call fn(a, b, record) for every pair that begins, stays or ends touching, during
--- collisions() (docs/space.md, "Sensors and events", gives the order). Several callbacks
--- run in the order they were registered; one registered while collisions() runs its
--- events gets them from the next event on. Returns fn.
---@param event string 'begin', 'stay' or 'end'
---@param fn function
---@return function fn
function Space:on(event, fn)
  if not isSpace(self) then badSelf(self, 'strike.Space:on') end
  checkEvent('strike.Space:on', event)
  if type(fn) ~= 'function' then
    fail(('strike.Space:on: argument 2 must be a function (a, b, record), got %s'):format(what(fn)))
  end
  local list = self._on[event]
  list[#list + 1] = fn
  self._listeners = self._listeners + 1
  return fn
end

--- Remove a callback registered with on (its first registration for that event): it is not
--- called again, even by the collisions() call in progress. Returns true when it was found.
---@param event string
---@param fn function
---@return boolean
function Space:off(event, fn)
  if not isSpace(self) then badSelf(self, 'strike.Space:off') end
  checkEvent('strike.Space:off', event)
  local list = self._on[event]
  for i = 1, #list do
    if list[i] == fn then
      if self._emE > 0 then
        -- (events are running, or waiting to run after an error: the lists keep their
        -- places, see emitEvents; the hole is closed when they are done)
        list[i] = false
        self._compact = true
      else
        table.remove(list, i)
      end
      self._listeners = self._listeners - 1
      return true
    end
  end
  return false
end

-- A record from the pool, or a new one. Each owns an MTV (`_m`) and a contact list (`_c`).
local function takeRecord(self)
  local pool = self._pool
  local n = #pool
  if n > 0 then
    local rec = pool[n]
    pool[n] = nil
    return rec
  end
  return { a = false, b = false, mtv = false, sensor = false, contacts = nil, _m = MTV(), _c = {}, _key = 0,
    _frame = 0, _since = 0, _order = 0, _begun = false, _ids = {}, _sa = {}, _sb = {}, _np = 0 }
end

-- Let go of the shapes an MTV (and a list of contact points) names.
local letGo = MTV._letGo
local function forget(m, c)
  letGo(m)
  local i, p = 1, c[1]
  while p do
    p.colliderShape, p.collidedShape = false, false
    i = i + 1
    p = c[i]
  end
  local spares = c._spares -- (the points past the count: strike/init.lua, S.ite)
  if spares then
    for j = 1, #spares do spares[j].colliderShape, spares[j].collidedShape = false, false end
  end
end

-- Give an ended record back to the pool, holding nothing of the game's.
local function poolRecord(self, rec)
  rec.a, rec.b, rec.mtv, rec.contacts, rec._begun = false, false, false, nil, false
  forget(rec._m, rec._c)
  local sa, sb = rec._sa, rec._sb
  for i = 1, #sa do sa[i], sb[i] = false, false end
  local pool = self._pool
  pool[#pool + 1] = rec
end

local function byOrder(r1, r2) return r1._order < r2._order end

-- The record's contacts (S.ite), each point marked `persisted` when the record's previous
-- contacts had a point with the same id between the same shapes.
local function contacts(self, rec)
  local ids, sa, sb, np = rec._ids, rec._sa, rec._sb, 0
  local c = rec.contacts
  if c then
    for i = 1, c.count do
      local p = c[i]
      np = np + 1
      ids[np], sa[np], sb[np] = p.id, p.colliderShape, p.collidedShape
    end
  end
  c = Space._ite(rec._m, rec._c)
  rec.contacts = c
  if c then
    for i = 1, c.count do
      local p = c[i]
      local id, pa, pb, persisted = p.id, p.colliderShape, p.collidedShape, false
      for j = 1, np do
        if ids[j] == id and sa[j] == pa and sb[j] == pb then
          persisted = true
          break
        end
      end
      p.persisted = persisted
    end
  end
  for i = 1, np do sa[i], sb[i] = false, false end -- (the last contacts' shapes: scratch, let go)
end

-- Are both bodies of the record still in the space, as the bodies it was made for (not
-- removed, nor removed and added again: a new rank)?
local function recordLive(self, rec)
  local a, b = rec.a, rec.b
  if rawget(a, '_space') ~= self or rawget(b, '_space') ~= self then return false end
  local rank = self._rank
  return rank[a._sid] * K + rank[b._sid] == rec._order
end

-- Run the events of the last collisions() from where they stand (the state the space keeps:
-- see Space:new), to the end: first 'end' for the pairs in _ended, then 'begin' or 'stay'
-- for the touching pairs in _prev, each with every callback of its kind in order. The place
-- is saved before each callback runs, so that when one raises an error, the next call of
-- collisions() goes on after it: each callback sees every event once, and every pair that
-- began ends once. A pair whose body was removed during the events (by a callback) gets no
-- more events now ('end' at the next call if it began); one that never began never ends.
local function emitEvents(self)
  local on, ended, prev = self._on, self._ended, self._prev
  local ne, n = self._emNe, self._emN
  local e, c = self._emE, self._emC
  local listen = self._listeners > 0
  while e <= n do
    local rec, kind, count
    if c == 1 then -- (the event starts: which kind, if any)
      if e <= ne then
        rec = ended[e]
        if rec._begun then kind = 'end' end
      else
        rec = prev[e - ne]
        if self._removals == self._emR or recordLive(self, rec) then
          if rec._begun then kind = 'stay' else kind = 'begin' end
          rec._begun = true
          if not listen then
            rec.contacts = nil
          elseif not rec.sensor then
            contacts(self, rec)
          else
            rec.contacts = nil
          end
        end
      end
      if kind then
        count = #on[kind]
        self._emKind, self._emCount = kind, count
      else
        count = 0
      end
    else -- (going on after an error, within an event)
      rec = e <= ne and ended[e] or prev[e - ne]
      kind, count = self._emKind, self._emCount
    end
    if count > 0 then
      local list = on[kind]
      for i = c, count do
        local f = list[i]
        if f then
          self._emE, self._emC = e, i + 1
          f(rec.a, rec.b, rec)
        end
      end
    end
    e, c = e + 1, 1
  end
  self._emE, self._emC = 0, 1
  for p = 1, ne do
    local rec = ended[p]
    ended[p] = false
    poolRecord(self, rec)
  end
  if self._compact then -- (close the holes off() left)
    self._compact = false
    for _, list in pairs(on) do
      local j = 0
      for i = 1, #list do
        local f = list[i]
        list[i] = nil
        if f then
          j = j + 1
          list[j] = f
        end
      end
    end
  end
end

------------------------------------------------------------------ collisions

-- Drop from list[1..k] the records that name a body removed since (by a filter or a
-- callback); returns the new count.
local function dropDead(self, list, k)
  local j = 0
  for i = 1, k do
    local rec = list[i]
    if recordLive(self, rec) then
      j = j + 1
      list[j] = rec
    end
  end
  trim(list, j)
  return j
end

local function collisionsOf(self, out)
  if self._emE > 0 then emitEvents(self) end -- (events an error stopped last time)
  flush(self)
  local buf = self._buf
  local np = self._tree:pairs(buf)
  local frame = self._frame + 1
  self._frame = frame
  self._nfresh = 0
  local removals = self._removals
  local body, rank, sensorOf, active, fresh = self._body, self._rank, self._sensor, self._active, self._fresh
  local mask, group, pf = self._mask, self._group, self._pairFilter
  local cur, ncur, sorted, last = self._cur, 0, true, -1
  local scratch = self._scratch
  for p = 1, np do
    local i, j = buf[2 * p - 1], buf[2 * p]
    local a, b = body[i], body[j]
    if a and b then -- (false: the pair filter removed one)
      local key = i * K + j
      if rank[i] > rank[j] then i, j = j, i end
      local g = group[i]
      -- (the usual case inline: no masks, groups or pair filter to ask)
      if (not mask[i] and not mask[j] and (g == 0 or g ~= group[j]) and not pf) or allowed(self, i, j) then
        a, b = body[i], body[j] -- (the pair filter may have removed either, or added a body in its place)
        if a and b then
          local rec = active[key]
          local order = rank[i] * K + rank[j]
          -- (a record of other bodies under a reused id, or of these bodies before one of them
          -- was removed and added again: that pair ended)
          if rec and (rec.a ~= a or rec.b ~= b or rec._order ~= order) then rec = nil end
          local m = rec and rec._m or scratch
          if collide(a, b, m) then
            if not rec then
              rec = takeRecord(self)
              rec._m, scratch = scratch, rec._m
              self._scratch = scratch
              rec.a, rec.b, rec._key, rec._since, rec.contacts, rec._begun = a, b, key, frame, nil, false
              active[key] = rec
              local nf = self._nfresh + 1
              self._nfresh, fresh[nf] = nf, rec
            end
            local sensor = sensorOf[i] or sensorOf[j]
            rec.sensor, rec.mtv, rec._frame = sensor, not sensor and rec._m, frame
            rec._order = order
            if order < last then sorted = false end
            last = order
            ncur = ncur + 1
            cur[ncur] = rec
          end
        end
      end
    end
  end
  trim(cur, ncur)
  if self._removals ~= removals then
    -- (the pair filter removed bodies: their pairs found before are not touching now)
    local k = 0
    for p = 1, ncur do
      local rec = cur[p]
      if recordLive(self, rec) then
        k = k + 1
        cur[k] = rec
      else
        rec._frame = 0
      end
    end
    trim(cur, k)
    ncur = k
  end
  if not sorted then table.sort(cur, byOrder) end
  -- The state first (which pairs ended, the new list, out), then the callbacks: a callback
  -- that raises an error leaves the space as consistent as one that returns.
  local prev, ended, ne = self._prev, self._ended, 0
  for p = 1, self._nprev do
    local rec = prev[p]
    if rec._frame ~= frame then -- (touching at the last call, not now: in the last call's order)
      if active[rec._key] == rec then active[rec._key] = nil end
      ne = ne + 1
      ended[ne] = rec
    end
  end
  for p = 1, self._nfresh do -- (made now and dropped above)
    local rec = fresh[p]
    fresh[p] = false
    if rec._frame ~= frame then
      if active[rec._key] == rec then active[rec._key] = nil end
      poolRecord(self, rec)
    end
  end
  self._nfresh = 0
  local k = 0
  for p = 1, ncur do
    local rec = cur[p]
    prev[p] = rec
    if not rec.sensor then
      k = k + 1
      out[k] = rec
    end
  end
  trim(prev, ncur)
  self._nprev = ncur
  trim(out, k)
  if self._listeners == 0 then -- (nobody to tell: the events are over at once)
    for p = 1, ncur do
      local rec = cur[p]
      rec._begun, rec.contacts = true, nil
    end
    for p = 1, ne do
      poolRecord(self, ended[p])
      ended[p] = false
    end
  else
    self._emE, self._emC, self._emNe, self._emN, self._emR = 1, 1, ne, ne + ncur, self._removals
    emitEvents(self)
  end
  if self._removals ~= removals then k = dropDead(self, out, k) end
  return out, k
end

-- collisions() interrupted by an error: when it came from the pair filter, the pairs of
-- this call are forgotten (the records it made go back to the pool; the next call starts
-- from the last one that finished); when it came from a callback, the events left wait for
-- the next call (emitEvents).
local function endCollisions(self, guard, ok, ...)
  self._inCollisions = false
  self._guard = guard
  if not guard then recover(self) end
  if not ok then
    local fresh = self._fresh
    for p = 1, self._nfresh do
      local rec = fresh[p]
      fresh[p] = false
      if self._active[rec._key] == rec then self._active[rec._key] = nil end
      poolRecord(self, rec)
    end
    self._nfresh = 0
    error((...), 0)
  end
  return ...
end

--- Every colliding pair of solid bodies (neither a sensor) that layers, masks, groups and
--- the pair filter allow, as records `{a =, b =, mtv =, sensor = false, contacts =}` (a added
--- before b; mtv as S.triking(a, b), from a toward b), in pair order. The records are the
--- space's: they are reused by the next call. Also runs the contact events (see on). The
--- pair filter and the callbacks may add, remove, move and query bodies (not call
--- collisions() again); pairs of a body they removed are not in the list.
---@param out table|nil
---@return table list
---@return integer n
function Space:collisions(out)
  if not isSpace(self) then badSelf(self, 'strike.Space:collisions') end
  checkOut('strike.Space:collisions', out, 1)
  if self._inCollisions then
    fail('strike.Space:collisions: called from the pair filter or an event callback of the same space\'s'
      .. ' collisions(), which is still running')
  end
  out = out or {}
  if self._pairFilter or self._listeners > 0 or self._emE > 0 then
    local guard = self._guard
    self._inCollisions, self._guard = true, true
    return endCollisions(self, guard, pcall(collisionsOf, self, out))
  end
  return collisionsOf(self, out)
end

------------------------------------------------------------------ queries

-- The candidates for the box, in rank order, into level.ids; returns the count.
local function candidates(self, level, x0, y0, x1, y1)
  local ids = level.ids
  local k = self._tree:query(x0, y0, x1, y1, ids)
  byRank(self, ids, k)
  return k
end

-- Is the body in this space?
local function present(self, b)
  return rawget(b, '_space') == self
end

-- Drop from list[1..k] the bodies (or the records whose `field` names a body) that a
-- filter removed from the space during the call, which began when the space had made
-- `removals` removals: a body removed and added again meanwhile too (it is not the body
-- the call found, and has another rank); returns the new count. Dropped records go past
-- it, where trimRecords keeps them as spares.
local function dropRemoved(self, list, k, field, removals)
  local gone = self._gone
  local j = 0
  for i = 1, k do
    local v = list[i]
    local b = field and v[field] or v
    if present(self, b) and (gone[b] or 0) <= removals then
      j = j + 1
      list[i], list[j] = list[j], v
    end
  end
  if not field then trim(list, j) end
  return j
end

-- Records that a query leaves in the caller's `out` (check's pairs, rayCastAll's hits) are
-- reused: the one at out[k] when it is ours (it has the field `mark`), else one from
-- out._spare, else a new one from make().
local function outRecord(out, k, mark, make)
  local rec = out[k]
  if type(rec) == 'table' and rawget(rec, mark) ~= nil then return rec end
  local spare = rawget(out, '_spare')
  if type(spare) ~= 'table' then spare = nil end
  local n = spare and #spare or 0
  local top = n > 0 and spare[n]
  if type(top) == 'table' and rawget(top, mark) ~= nil then -- (an `out` passed to both kinds holds both)
    rec = top
    spare[n] = nil
  else
    rec = make()
  end
  out[k] = rec
  return rec
end

-- Clear out past k, keeping our records (marked by `mark`) in out._spare, without the bodies
-- and shapes they named (a spare must not keep them alive).
local function trimRecords(out, k, mark)
  local i = k + 1
  local rec = out[i]
  if rec == nil then
    trim(out, k)
    return
  end
  local spare = rawget(out, '_spare')
  if type(spare) ~= 'table' then
    spare = {}
    out._spare = spare
  end
  while rec ~= nil do
    if type(rec) == 'table' and rawget(rec, mark) ~= nil then
      rec.a, rec.b, rec.body, rec.shape = nil, nil, nil, nil
      spare[#spare + 1] = rec
    end
    out[i] = nil
    i = i + 1
    rec = out[i]
  end
  trim(out, k)
end

-- (check's records are marked `_check`: the space's own pair records, from collisions(), have
-- an `_m` too, and an `out` that holds them must not have them reused)
local function newPair() return { a = false, b = false, mtv = false, _m = MTV(), _check = true } end
local function newHit() return { _rank = 0 } end

-- May a query's filter (checked: nil, a function or a layer filter) run game code?
local function gameFilter(f) return type(f) == 'function' end

local function checkOf(self, body, filterArg, out)
  flush(self)
  local self_id = ownId(self, 'strike.Space:check', body)
  local inside = self_id and true
  local k = 0
  if not (inside and self._sensor[self_id]) then
    local x0, y0, x1, y1
    if inside then x0, y0, x1, y1 = self._tree:box(self_id) else x0, y0, x1, y1 = body:getBounds() end
    local level = enter(self)
    local removals = self._removals
    local ids, bodies, layer, sensor, rank = level.ids, self._body, self._layer, self._sensor, self._rank
    local n = candidates(self, level, x0, y0, x1, y1)
    for c = 1, n do
      local id = ids[c]
      local other = bodies[id]
      -- (other is false when a filter removed it since)
      if other and id ~= self_id and not sensor[id] and queryFilter(filterArg, other, layer[id]) then
        local ok = true
        -- (the filter may have removed the body asked about, or this one: then no more pairs
        -- of it, nor this one)
        if inside and bodies[self_id] ~= body then break end
        if bodies[id] ~= other then ok = false elseif inside then
          if rank[self_id] < rank[id] then ok = allowed(self, self_id, id) else ok = allowed(self, id, self_id) end
        end
        if ok and bodies[id] == other and (not inside or bodies[self_id] == body) then
          local rec = outRecord(out, k + 1, '_check', newPair)
          if collide(body, other, rec._m) then
            k = k + 1
            rec.a, rec.b, rec.mtv = body, other, rec._m
          end
        end
      end
    end
    leave(self, level)
    if self._removals ~= removals then k = dropRemoved(self, out, k, 'b', removals) end
  end
  trimRecords(out, k, '_check')
  return out, k
end

--- The solid bodies colliding with `body` (in this space or not), as records
--- `{a = body, b = other, mtv =}` (mtv as S.triking(body, other)) in rank order. For a body
--- in the space, layers, masks, groups and the pair filter apply, and a sensor collides with
--- nothing (use queryShape); `filter` applies to the others. Sensors are never included.
---@param body strike.Collider|strike.Shape
---@param filterArg function|table|nil
---@param out table|nil
---@return table list
---@return integer n
function Space:check(body, filterArg, out)
  if not isSpace(self) then badSelf(self, 'strike.Space:check') end
  checkBody('strike.Space:check', body, 1)
  checkQuery(filterArg, 'strike.Space:check', 2)
  checkOut('strike.Space:check', out, 3)
  out = out or {}
  if not self._guard and (gameFilter(filterArg) or self._pairFilter) then
    return protect(self, checkOf, body, filterArg, out)
  end
  return checkOf(self, body, filterArg, out)
end

local function number(fname, v, name)
  if type(v) ~= 'number' or not finite(v) then
    fail(('%s: %s must be a finite number, got %s'):format(fname, name, describe(v)))
  end
  return v
end

local function queryPointOf(self, x, y, filterArg, out)
  flush(self)
  local level = enter(self)
  local removals = self._removals
  local ids, bodies, layer = level.ids, self._body, self._layer
  local n, k = candidates(self, level, x, y, x, y), 0
  for c = 1, n do
    local id = ids[c]
    local b = bodies[id]
    if b and queryFilter(filterArg, b, layer[id]) and b:containsPoint(x, y) then
      k = k + 1
      out[k] = b
    end
  end
  leave(self, level)
  if self._removals ~= removals then k = dropRemoved(self, out, k, nil, removals) end
  trim(out, k)
  return out, k
end

--- The bodies containing the point (x, y) (as their containsPoint), sensors included, in
--- rank order.
---@param x number
---@param y number
---@param filterArg function|table|nil
---@param out table|nil
---@return table list
---@return integer n
function Space:queryPoint(x, y, filterArg, out)
  if not isSpace(self) then badSelf(self, 'strike.Space:queryPoint') end
  number('strike.Space:queryPoint', x, 'x')
  number('strike.Space:queryPoint', y, 'y')
  checkQuery(filterArg, 'strike.Space:queryPoint', 3)
  checkOut('strike.Space:queryPoint', out, 4)
  out = out or {}
  if not self._guard and gameFilter(filterArg) then return protect(self, queryPointOf, x, y, filterArg, out) end
  return queryPointOf(self, x, y, filterArg, out)
end

-- The bodies colliding with `probe` (a shape or collider; skipped itself), as queryShape.
-- `level` is the query's scratch (enter), which this leaves.
local function overlapping(self, level, probe, filterArg, out)
  flush(self)
  local removals = self._removals
  local x0, y0, x1, y1 = probe:getBounds()
  local ids, bodies, layer, scratch = level.ids, self._body, self._layer, self._scratch
  local n, k = candidates(self, level, x0, y0, x1, y1), 0
  for c = 1, n do
    local id = ids[c]
    local b = bodies[id]
    if b and b ~= probe and queryFilter(filterArg, b, layer[id]) and collide(probe, b, scratch) then
      k = k + 1
      out[k] = b
    end
  end
  leave(self, level)
  if self._removals ~= removals then k = dropRemoved(self, out, k, nil, removals) end
  trim(out, k)
  return out, k
end

-- A side of queryRect's rectangle: a length strike accepts (limits.lua).
local function side(fname, v)
  if type(v) ~= 'number' or not (v >= limits.MIN_LENGTH and v <= limits.MAX_LENGTH) then
    fail(('%s: w and h must be numbers from %s to %s, got %s'):format(fname, describe(limits.MIN_LENGTH),
      describe(limits.MAX_LENGTH), describe(v)))
  end
end

local function queryRectOf(self, x, y, w, h, filterArg, out)
  local level = enter(self)
  local probe = level.probe
  if not probe then
    probe = Rectangle(0, 0, 1, 1)
    probe:_ownGeometry() -- (changed in place below: a table no game's 1 by 1 rectangle shares)
    level.probe = probe
  end
  -- (the probe's local geometry set in place: corners at (+-w/2, +-h/2), as the
  -- constructor lays them out, normals unchanged; then its centre)
  local hw, hh = w / 2, h / 2
  local l = probe._l
  l[1], l[2], l[5], l[6], l[9], l[10], l[13], l[14] = -hw, -hh, hw, -hh, hw, hh, -hw, hh
  -- (and its sizes, width and height, after its 4 vertices' 16 numbers: VertexShape.lua)
  l[17], l[18], probe[AREA], probe[RADIUS] = w, h, w * h, sqrt(hw * hw + hh * hh)
  probe[X], probe[Y] = x + hw, y + hh
  probe:_touch()
  return overlapping(self, level, probe, filterArg, out)
end

--- The bodies overlapping the rectangle with its minimum corner at (x, y), w wide and h
--- high (as getBbox gives it; touching is not overlapping), exactly, sensors included, in
--- rank order.
---@param x number
---@param y number
---@param w number
---@param h number
---@param filterArg function|table|nil
---@param out table|nil
---@return table list
---@return integer n
function Space:queryRect(x, y, w, h, filterArg, out)
  if not isSpace(self) then badSelf(self, 'strike.Space:queryRect') end
  local fname = 'strike.Space:queryRect'
  number(fname, x, 'x')
  number(fname, y, 'y')
  side(fname, w)
  side(fname, h)
  if not finite(abs(x) + abs(y) + w + h) then -- (as every shape: |x| + |y| + radius finite)
    fail(fname .. ': the rectangle is too far out (|x| + |y| + w + h must be finite)')
  end
  checkQuery(filterArg, fname, 5)
  checkOut(fname, out, 6)
  out = out or {}
  if not self._guard and gameFilter(filterArg) then return protect(self, queryRectOf, x, y, w, h, filterArg, out) end
  return queryRectOf(self, x, y, w, h, filterArg, out)
end

local function queryShapeOf(self, shape, filterArg, out)
  return overlapping(self, enter(self), shape, filterArg, out)
end

--- The bodies colliding with a shape or collider (as S.triking; it need not be in the
--- space, and is skipped when it is), sensors included, in rank order.
---@param shape strike.Shape|strike.Collider
---@param filterArg function|table|nil
---@param out table|nil
---@return table list
---@return integer n
function Space:queryShape(shape, filterArg, out)
  if not isSpace(self) then badSelf(self, 'strike.Space:queryShape') end
  checkBody('strike.Space:queryShape', shape, 1)
  checkQuery(filterArg, 'strike.Space:queryShape', 2)
  checkOut('strike.Space:queryShape', out, 3)
  out = out or {}
  if not self._guard and gameFilter(filterArg) then return protect(self, queryShapeOf, shape, filterArg, out) end
  return queryShapeOf(self, shape, filterArg, out)
end

------------------------------------------------------------------ rays

-- Validate a ray; returns its unit direction and maximum distance.
local function checkRay(fname, x, y, dx, dy, maxDistance)
  number(fname, x, 'x')
  number(fname, y, 'y')
  number(fname, dx, 'dx')
  number(fname, dy, 'dy')
  local ux, uy = limits.unit(dx, dy)
  if not ux then fail(('%s: the direction (dx, dy) must not be (0, 0)'):format(fname)) end
  if maxDistance == nil then return ux, uy, huge end
  if type(maxDistance) ~= 'number' or not (maxDistance >= 0) then -- luacheck: ignore 581 (NaN)
    fail(('%s: maxDistance must be a number >= 0 or nil, got %s'):format(fname, describe(maxDistance)))
  end
  return ux, uy, maxDistance
end

local rayCast, leavesRayCast, leafList = ray.rayCast, ray.leavesRayCast, Collider._leafList

-- body:rayCast without its argument checks (the same arithmetic: (dx, dy) as the caller
-- gave it, made a unit vector once, as body:rayCast does): distance, point, normal and the
-- shape hit, or nil.
local function rayBody(b, x, y, dx, dy, maxDistance)
  if b._pose then
    local d, hx, hy, nx, ny = rayCast(b, x, y, dx, dy, maxDistance)
    return d, hx, hy, nx, ny, b
  end
  local leaves, n = leafList(b)
  return leavesRayCast(leaves, n, x, y, dx, dy, maxDistance)
end

-- Test body `id` (b) against the ray of `level` and keep its hit when it is nearer than the
-- best so far, or as near and added earlier; return the distance to beat.
local function rayTry(self, level, id, b, best)
  local f = level.filter
  if f then
    if type(f) == 'function' then
      if not verdict(self, level, f, b, id) then return best end
      if self._body[id] ~= b then return best end -- (the filter removed it)
    elseif not queryFilter(f, b, self._layer[id]) then
      return best
    end
  end
  local d, px, py, nx, ny, shape = rayBody(b, level.x, level.y, level.dx, level.dy, best)
  local rank = self._rank[id]
  if d and (d < best or not level.hit or rank < level.rank) then
    level.hit, level.rank, level.d, level.shape = b, rank, d, shape
    level.hx, level.hy, level.nx, level.ny = px, py, nx, ny
    return d
  end
  return best
end

-- rayCast's visitor (strike/space/tree.lua, rayVisit): test body `id`, entered at t. When
-- a filter changed the tree meanwhile, the walk stops (-1: nothing is that near) and
-- rayCastOf starts again without it.
local function rayVisit(level, id, _, best)
  local self = level.space
  local b = self._body[id]
  if b then
    best = rayTry(self, level, id, b, best)
    if self._removals ~= level.removals or self._tree.version ~= level.version then return -1 end
  end
  return best
end

local function rayCastOf(self, x, y, dx, dy, ux, uy, maxT, filterArg)
  flush(self)
  local level = enter(self)
  level.stamp = level.stamp + 1
  level.x, level.y, level.dx, level.dy, level.filter, level.hit = x, y, dx, dy, filterArg or false, false
  local tree = self._tree
  local removals, version = self._removals, tree.version
  level.removals, level.version = removals, version
  tree:rayVisit(x, y, ux, uy, maxT, rayVisit, level, level.stack, level.tstack)
  if self._removals ~= removals or tree.version ~= version then
    -- A filter changed the tree during the walk (removed bodies, or ran a query that brought
    -- the tree up to date with moves and adds): the walk may have missed boxes, and the best
    -- hit may be gone. Again over every candidate along the whole ray, from a list taken
    -- first (no walk to spoil), each filter's verdict kept from the walk; every hit kept, and
    -- the nearest of the bodies still in the space chosen at the end.
    local ids, ts, hits = level.ids, level.ts, level.hits
    if not hits then
      hits = {}
      level.hits = hits
    end
    local n = tree:rayCandidates(x, y, ux, uy, maxT, ids, ts)
    local bodies, f, nh = self._body, level.filter, 0
    for i = 1, n do
      local id = ids[i]
      local b = bodies[id]
      if b and (not f or (type(f) == 'function' and verdict(self, level, f, b, id) or type(f) == 'table'
        and queryFilter(f, b, self._layer[id]))) and bodies[id] == b then
        local d, px, py, nx, ny, shape = rayBody(b, x, y, dx, dy, maxT)
        if d then
          hits[nh + 1], hits[nh + 2], hits[nh + 3], hits[nh + 4] = b, d, px, py
          hits[nh + 5], hits[nh + 6], hits[nh + 7], hits[nh + 8] = nx, ny, shape, self._rank[id]
          nh = nh + 8
        end
      end
    end
    level.hit = false
    for h = 1, nh, 8 do
      local b, d, rank = hits[h], hits[h + 1], hits[h + 7]
      if present(self, b) and (not level.hit or d < level.d or d == level.d and rank < level.rank) then
        level.hit, level.d, level.hx, level.hy = b, d, hits[h + 2], hits[h + 3]
        level.nx, level.ny, level.shape, level.rank = hits[h + 4], hits[h + 5], hits[h + 6], rank
      end
    end
    for h = 1, nh do hits[h] = false end -- (nothing kept alive)
  end
  leave(self, level)
  local hit, shape = level.hit, level.shape
  level.hit, level.filter, level.shape = false, false, false -- (the level keeps nothing alive)
  if not hit then return nil end
  return hit, level.d, level.hx, level.hy, level.nx, level.ny, shape
end

--- The closest body the ray from (x, y) along (dx, dy) hits within maxDistance (default
--- math.huge; dx, dy need not be a unit vector, distances are in units of length): body,
--- distance, hit point, unit normal and the shape hit; nil when none. Ties go to the body
--- added first. A ray starting inside a body hits it where it leaves (as body:rayCast).
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number|nil
---@param filterArg function|table|nil
---@return strike.Collider|strike.Shape|nil body
---@return number distance
---@return number x
---@return number y
---@return number nx
---@return number ny
---@return strike.Shape shape
function Space:rayCast(x, y, dx, dy, maxDistance, filterArg)
  if not isSpace(self) then badSelf(self, 'strike.Space:rayCast') end
  local ux, uy, maxT = checkRay('strike.Space:rayCast', x, y, dx, dy, maxDistance)
  checkQuery(filterArg, 'strike.Space:rayCast', 6)
  if not self._guard and gameFilter(filterArg) then
    return protect(self, rayCastOf, x, y, dx, dy, ux, uy, maxT, filterArg)
  end
  return rayCastOf(self, x, y, dx, dy, ux, uy, maxT, filterArg)
end

local function byDistance(r1, r2)
  local d1, d2 = r1.distance, r2.distance
  if d1 ~= d2 then return d1 < d2 end
  return r1._rank < r2._rank
end

local function rayCastAllOf(self, x, y, dx, dy, ux, uy, maxT, filterArg, out)
  flush(self)
  local level = enter(self)
  local removals = self._removals
  local ids, ts = level.ids, level.ts
  local n = self._tree:rayCandidates(x, y, ux, uy, maxT, ids, ts)
  local bodies, layer, rank, k = self._body, self._layer, self._rank, 0
  for i = 1, n do
    local id = ids[i]
    local b = bodies[id]
    if b and queryFilter(filterArg, b, layer[id]) then
      local d, px, py, nx, ny, shape = rayBody(b, x, y, dx, dy, maxT)
      if d then
        k = k + 1
        local rec = outRecord(out, k, '_rank', newHit)
        rec.body, rec.distance, rec.x, rec.y, rec.nx, rec.ny, rec.shape = b, d, px, py, nx, ny, shape
        rec._rank = rank[id] or 0
      end
    end
  end
  leave(self, level)
  if self._removals ~= removals then k = dropRemoved(self, out, k, 'body', removals) end
  trimRecords(out, k, '_rank')
  local sorted = true
  for j = 2, k do
    if byDistance(out[j], out[j - 1]) then
      sorted = false
      break
    end
  end
  if not sorted then table.sort(out, byDistance) end
  return out, k
end

--- Every body the ray hits within maxDistance, once each at its first crossing, as records
--- `{body =, distance =, x =, y =, nx =, ny =, shape =}` sorted by distance (ties: the body
--- added first). Records in `out` are reused.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number|nil
---@param filterArg function|table|nil
---@param out table|nil
---@return table list
---@return integer n
function Space:rayCastAll(x, y, dx, dy, maxDistance, filterArg, out)
  if not isSpace(self) then badSelf(self, 'strike.Space:rayCastAll') end
  local ux, uy, maxT = checkRay('strike.Space:rayCastAll', x, y, dx, dy, maxDistance)
  checkQuery(filterArg, 'strike.Space:rayCastAll', 6)
  checkOut('strike.Space:rayCastAll', out, 7)
  out = out or {}
  if not self._guard and gameFilter(filterArg) then
    return protect(self, rayCastAllOf, x, y, dx, dy, ux, uy, maxT, filterArg, out)
  end
  return rayCastAllOf(self, x, y, dx, dy, ux, uy, maxT, filterArg, out)
end

------------------------------------------------------------------ motion

--- The internals that Space:cast, Space:move and Space:addResponse share (strike/space/
--- motion.lua, which strike/init.lua loads after this file): the query levels, flush, the
--- candidates of a box, the pair rules and the argument checks.
Space._internals = {
  enter = enter, leave = leave, flush = flush, candidates = candidates, allowed = allowed, isSpace = isSpace,
  checkBody = checkBody, idOf = idOf, ownId = ownId, protect = protect, present = present,
}

------------------------------------------------------------------ drawing support

--- Visit the broadphase's boxes: fn(ctx, minx, miny, maxx, maxy, depth, isLeaf, moving) for every
--- node of its two trees (Tree:eachNode). For S.howSpace and tests.
---@param fn function
---@param ctx any
function Space:_eachNode(fn, ctx)
  flush(self)
  self._tree:eachNode(fn, ctx)
end

return Space
