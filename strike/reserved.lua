--- The names strike keeps on a body (README.md, "Your data on bodies"): its integer keys (the
--- world data and caches laid out in strike/base/layout.lua), every name starting with `_`,
--- and its methods' names. Every other name is the game's: strike never reads or writes it.
---
--- strike's own named fields, on a shape:
---   _pose     the pose stamp (a number, new on every move)            base/Shape.lua
---   _kind     the kind the narrow phase dispatches on                 base/Shape.lua
---   _parent   the collider holding it, or nil                         colliders/Collider.lua
---   _seams    the seam faces of a compound's piece (false, or none:   base/VertexShape.lua
---             then it reads its class's false)
---   _l        its local geometry and its class's sizes, often shared  base/VertexShape.lua
--- on a collider:
---   _shapes   its children, a list whose slot 0 names the collider   colliders/Collider.lua
---   _parent, _leaves, _nleaves, _leafPos, _single, _massOK, _clean, _loop   (the caches)
--- on a body in a space: _space (the space) and _sid (its proxy id)    space/Space.lua
--- and, on every class (read through the instance, never set on it): `_type`, the class
--- marker ('shape', 'collider', 'space', 'mtv'), beside the public `type`, `name`, `kind`.
---
--- A game that overwrites one of them gets an error naming the field at the next call that
--- relies on it, never a wrong answer. The happy paths pay one comparison they mostly make
--- anyway (a kernel looked up by `_kind`, a space's own body at `_sid`, a list's owner, a
--- class marker); when one fails, the functions here find what was changed and say so. They
--- run only on those failure paths, so they may walk, scan and allocate.
local ROOT = (...):match('^(.-)%.[^%.]+$')
local check = require(ROOT .. '.check')
local kinds = require(ROOT .. '.collide.dispatch').kind

local describe, fail = check.describe, check.fail
local type, rawget, getmetatable = type, rawget, getmetatable

local reserved = {}

--- What every error about a changed field ends with.
reserved.RULE = 'fields starting with _ are strike\'s (README, "Your data on bodies")'

--- The class marker of a strike instance: 'shape', 'collider', 'space' or 'mtv' (read from its
--- class, so a game's own `_type` on the instance does not hide it); nil for anything else,
--- classes included.
---@param v any
---@return string|nil
function reserved.classType(v)
  if type(v) ~= 'table' or rawget(v, '__index') == v then return nil end
  local mt = getmetatable(v)
  if type(mt) ~= 'table' then return nil end
  local t = mt._type
  if type(t) ~= 'string' then return nil end
  return t
end
local classType = reserved.classType

-- Is `v` (a table) in the list `list` (a table), at an index from 1 on?
local function listed(list, v)
  local i = 1
  local e = rawget(list, 1)
  while e ~= nil do
    if e == v then return true end
    i = i + 1
    e = rawget(list, i)
  end
  return false
end

-- The slot of the space's body list that holds `v`, or nil.
local function slotIn(space, v)
  local bodies = rawget(space, '_body')
  if type(bodies) ~= 'table' then return nil end
  for id, b in pairs(bodies) do
    if b == v then return id end
  end
  return nil
end

-- Was the shape `v` built (its constructor ran)? Any of the fields it sets then.
local function builtShape(v)
  return rawget(v, '_pose') ~= nil or rawget(v, '_kind') ~= nil or rawget(v, '_seams') ~= nil
end

-- Was the collider `v` built? Any of the fields Collider.new (or its first add) sets.
local function builtCollider(v)
  return rawget(v, '_single') ~= nil or rawget(v, '_nleaves') ~= nil or rawget(v, '_shapes') ~= nil
end

--- The first of strike's fields of the strike object `v` (not of its members) that is not
--- as strike left it, and its value: `field, value`; nil when none is found. It checks the
--- fields strike relies on: `_type`; a shape's `_pose`, `_kind`, `_seams`; a collider's
--- `_shapes` (and each child's `_parent`: `field` is then '_parent' and the third result the
--- child), its leaf cache; and everyone's `_parent`, `_space`, `_sid`.
---@param v any
---@return string|nil field
---@return any value
---@return table|nil member a child whose own field it is, when not v's
function reserved.fieldOf(v)
  local t = classType(v)
  if t ~= 'shape' and t ~= 'collider' then return nil end
  local own = rawget(v, '_type')
  if own ~= nil then return '_type', own end
  if t == 'shape' then
    if builtShape(v) then
      local pose = rawget(v, '_pose')
      if type(pose) ~= 'number' then return '_pose', pose end
      local kind = rawget(v, '_kind')
      if kind == nil or kinds[kind] == nil then return '_kind', kind end
      local seams = rawget(v, '_seams')
      if seams ~= nil and seams ~= false and type(seams) ~= 'table' then return '_seams', seams end
    end
    -- (a shape has no children: a `_shapes` would make strike take it for a collider)
    if rawget(v, '_shapes') ~= nil then return '_shapes', rawget(v, '_shapes') end
  elseif builtCollider(v) then
    local list = rawget(v, '_shapes')
    if type(list) ~= 'table' or rawget(list, 0) ~= v then return '_shapes', list end
    local i, c = 1, rawget(list, 1)
    while c ~= nil do
      local ct = classType(c)
      if ct ~= 'shape' and ct ~= 'collider' then return '_shapes', list end
      if rawget(c, '_parent') ~= v then return '_parent', rawget(c, '_parent'), c end
      i = i + 1
      c = rawget(list, i)
    end
    local n = rawget(v, '_nleaves')
    if type(n) ~= 'number' then return '_nleaves', n end
    if n >= 0 and type(rawget(v, '_leaves')) ~= 'table' then return '_leaves', rawget(v, '_leaves') end
    local single = rawget(v, '_single')
    if single ~= false and classType(single) ~= 'shape' then return '_single', single end
    for _, flag in ipairs({ '_massOK', '_clean' }) do
      if type(rawget(v, flag)) ~= 'boolean' then return flag, rawget(v, flag) end
    end
  end
  local p = rawget(v, '_parent')
  if p ~= nil and not (classType(p) == 'collider' and type(rawget(p, '_shapes')) == 'table'
    and listed(rawget(p, '_shapes'), v)) then
    return '_parent', p
  end
  local space, id = rawget(v, '_space'), rawget(v, '_sid')
  if space ~= nil and space ~= false then
    if classType(space) ~= 'space' then return '_space', space end
    local bodies = rawget(space, '_body')
    if type(bodies) ~= 'table' or id == nil or bodies[id] ~= v then
      if slotIn(space, v) then return '_sid', id end
      return '_space', space
    end
  elseif id ~= nil then
    return '_sid', id -- (a body strike took out of its space, or never put in one, has no _sid)
  end
  return nil
end
local fieldOf = reserved.fieldOf

--- fieldOf over `v` and everything it holds, then the colliders holding it: the body whose
--- field it is, the field and its value; nil when every one is as strike left it. (A walk
--- with a stack of its own: a failure path.)
---@param v any
---@return table|nil body
---@return string field
---@return any value
function reserved.find(v)
  local t = classType(v)
  if t ~= 'shape' and t ~= 'collider' then return nil end
  local stack, n, seen = { v }, 1, {}
  while n > 0 do
    local b = stack[n]
    stack[n] = nil
    n = n - 1
    if not seen[b] then
      seen[b] = true
      local field, value, member = fieldOf(b)
      if field then return member or b, field, value end
      local list = classType(b) == 'collider' and rawget(b, '_shapes')
      if type(list) == 'table' then
        local i, c = 1, rawget(list, 1)
        while c ~= nil do
          n = n + 1
          stack[n] = c
          i = i + 1
          c = rawget(list, i)
        end
      end
    end
  end
  local p = rawget(v, '_parent')
  while classType(p) == 'collider' and not seen[p] do
    seen[p] = true
    local field, value, member = fieldOf(p)
    if field then return member or p, field, value end
    p = rawget(p, '_parent')
  end
  return nil
end
local find = reserved.find

--- The error for `body`'s field `field` (now `value`), `v` being what the call was given:
--- `owner` names it in the message ('argument 1', 'the collider'). `body` may be `v` or a
--- body it holds or that holds it.
---@param fname string
---@param owner string
---@param v table
---@param body table
---@param field string
---@param value any
function reserved.fail(fname, owner, v, body, field, value)
  local whose
  if body == v then
    whose = owner .. '\'s'
  else
    local up = rawget(v, '_parent')
    local holder = false
    while up ~= nil and not holder do
      holder = up == body
      up = type(up) == 'table' and rawget(up, '_parent') or nil
    end
    whose = ('%s %s a %s whose'):format(owner, holder and 'is held by' or 'holds', classType(body) or 'body')
  end
  fail(('%s: %s field %s was changed (now %s); %s'):format(fname, whose, field, describe(value), reserved.RULE))
end

--- Raise the error naming the changed field, when `v` (a strike body, given to `fname` as
--- `owner`) or a body it holds or that holds it has one; return otherwise (the caller then
--- raises its own error).
---@param fname string
---@param owner string
---@param v any
function reserved.check(fname, owner, v)
  local body, field, value = find(v)
  if body then reserved.fail(fname, owner, v, body, field, value) end
end

--- The error for a shape whose `_kind` names no registered kind (the narrow phase, a ray
--- or a draw met it), held by the argument `owner` of `fname` when known. Raises.
---@param fname string
---@param s table the shape
---@param owner string|nil
---@param v table|nil what the call was given
function reserved.badKind(fname, s, owner, v)
  reserved.fail(fname, owner or 'a shape', v or s, s, '_kind', rawget(s, '_kind'))
end

return reserved
