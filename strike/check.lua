--- Argument validation for the public boundary. Errors are raised at the first stack
--- frame outside the strike folder, i.e. at the line of the game that made the bad call,
--- however deep inside strike (constructors called through `Class(...)`, `super.new`)
--- the check happened. Only the error path pays for the stack walk.
local check = {}

local ROOT = (...):match('^(.-)%.[^%.]+$')
-- strike/reserved.lua, loaded by the failure paths that need it (it requires this file)
local function reserved() return require(ROOT .. '.reserved') end

local getinfo = debug and debug.getinfo
local huge = math.huge

-- The chunk-name prefix shared by every file of this library, e.g. "@./strike/".
local PREFIX = getinfo and getinfo(1, 'S').source:match('^(.*[/\\])[^/\\]*$')

--- Raise `msg` at the caller's line: the first function outside the strike folder.
---@param msg string
function check.fail(msg)
  local level = 2
  if PREFIX then
    while true do
      local info = getinfo(level, 'S')
      if not info then level = 2 break end
      local src = info.source
      if info.what ~= 'C' and info.what ~= 'tail' and src:sub(1, #PREFIX) ~= PREFIX then break end
      level = level + 1
    end
    -- error() counts its own caller (this function) as level 1.
    level = level - 1
  end
  error(msg, level + 1)
end

--- A short, readable description of any value for error messages.
---@param v any
---@return string
function check.describe(v)
  local t = type(v)
  if t == 'number' then
    if v ~= v then return 'nan' end
    if v == huge then return 'inf' end
    if v == -huge then return '-inf' end
    return tostring(v)
  elseif t == 'string' then
    return ('string %q'):format(#v > 40 and v:sub(1, 40) .. '...' or v)
  elseif t == 'nil' or t == 'boolean' then
    return tostring(v)
  end
  return t
end

--- Like describe, but names strike's own objects by their class's marker `_type` (never a
--- field of the instance, which may be a game's): "a shape", "a collider", "an MTV", "a space".
---@param v any
---@return string
function check.what(v)
  local t = reserved().classType(v)
  if t then return t == 'mtv' and 'an MTV' or 'a ' .. t end
  return check.describe(v)
end

--- Raise the error for an `out` argument that is not a table or nil, or is one of strike's
--- objects (a shape, a collider, an MTV: their classes have a `_type` field).
---@param fname string
---@param out any
function check.badOut(fname, out)
  check.fail(('%s: out must be a table or nil, got %s'):format(fname, check.what(out)))
end

-- What a method's `self` was, for check.badSelf: strike's objects by what they are.
local function describeSelf(v)
  local t = type(v)
  if t == 'number' then return 'the number ' .. check.describe(v) end
  if t == 'string' then return 'the ' .. check.describe(v) end
  if t == 'nil' or t == 'boolean' then return tostring(v) end
  if t ~= 'table' then return 'a ' .. t end
  if rawget(v, '__index') == v then return 'a class' end
  local kind = reserved().classType(v)
  if kind == 'shape' then return 'a shape' end
  if kind == 'collider' then return 'a collider' end
  if kind == 'mtv' then return 'an MTV' end
  if kind == 'space' then return 'a space' end
  return 'a table that is no strike object'
end

--- The error for a method called with '.' instead of ':' (`k.add(b)` for `k:add(b)`): its
--- `self` is not an object it works on. Methods test their `self` inline (one type() and
--- one field read, nothing called on the happy path) and call this only when the test
--- fails; the error is raised at the caller's line. `fname` names the method
--- ('strike.Collider:add'); `on`, when given, says what to call it on ('a class').
---@param self any
---@param fname string
---@param on string|nil
function check.badSelf(self, fname, on)
  -- (a body whose fields the game changed: name the field, not the call)
  local t = reserved().classType(self)
  if t == 'shape' or t == 'collider' then reserved().check(fname, 'the ' .. t, self) end
  check.fail(("%s: called with '.' instead of ':' (self is %s); call it with ':'%s"):format(fname,
    describeSelf(self), on and (' on ' .. on) or ''))
end

--- The failure path of a collider method's inline test of its `self`, `type(self) ~= 'table'
--- or self._shapes == nil` (an own field: cheaper than the class's marker). Returns when
--- `self` is a collider after all, one whose constructor has not made its list of children
--- yet (Collider:add makes it: a constructor may add before calling Collider.new); otherwise
--- raises check.badSelf's error, which names a field of strike's the game changed.
---@param self any
---@param fname string
function check.badCollider(self, fname)
  if reserved().classType(self) == 'collider' and rawget(self, '_single') == nil and rawget(self, '_nleaves') == nil
    and rawget(self, '_shapes') == nil then
    return
  end
  check.badSelf(self, fname)
end

--- The key of table `t` that `known` lacks, the least one when there are several (strings
--- before other keys, each kind in order), so that an error names the same key whatever
--- `pairs` order is; nil when `known` has every key.
---@param t table
---@param known table
---@return any
function check.unknownKey(t, known)
  local best, bestRank
  for k in pairs(t) do
    if not known[k] then
      local rank = (type(k) == 'string' and '1' or type(k) == 'number' and '2' or '3' .. type(k)) .. ':'
        .. (type(k) == 'number' and ('%024.6f'):format(k) or tostring(k))
      if not best or rank < bestRank then best, bestRank = k, rank end
    end
  end
  return best
end

---@param v any
---@return boolean
local function finite(v)
  return type(v) == 'number' and v - v == 0
end
--- True for a number that is neither NaN nor infinite.
check.finite = finite

--- Require a finite number.
---@param v any
---@param fname string
---@param what string
---@return number
function check.number(v, fname, what)
  if not finite(v) then
    check.fail(('%s: %s must be a finite number, got %s'):format(fname, what, check.describe(v)))
  end
  return v
end

--- Require a finite number, or nil (then return `default`).
---@param v any
---@param fname string
---@param what string
---@param default any
---@return any
function check.optNumber(v, fname, what, default)
  if v == nil then return default end
  return check.number(v, fname, what)
end

--- Require a finite number > 0.
---@param v any
---@param fname string
---@param what string
---@return number
function check.positive(v, fname, what)
  if not finite(v) or v <= 0 then
    check.fail(('%s: %s must be a finite number > 0, got %s'):format(fname, what, check.describe(v)))
  end
  return v
end

--- Require an integer in [lo, hi].
---@param v any
---@param fname string
---@param what string
---@param lo integer
---@param hi integer
---@return integer
function check.integer(v, fname, what, lo, hi)
  if not finite(v) or v % 1 ~= 0 or v < lo or v > hi then
    check.fail(('%s: %s must be an integer from %d to %d, got %s'):format(fname, what, lo, hi, check.describe(v)))
  end
  return v
end

--- Coordinates given as x1, y1, x2, y2, ... or as one table {x1, y1, ...}: split into
--- arrays of finite numbers, or raise an error naming the bad value.
---@param fname string
---@param ... number|number[]
---@return number[] xs, number[] ys, integer n
function check.coordinates(fname, ...)
  local args, count = ..., select('#', ...)
  local direct = false -- (read the arguments with select rather than pack them)
  if type(args) == 'table' then
    count = #args
  elseif count <= 64 then
    -- (a few coordinates, as a rectangle's or a regular polygon's: LuaJIT cannot compile
    -- `{ ... }`, and packing them cost 7.5 us a call against 0.2 us; select reads each pair
    -- in O(count), which only matters for long lists, packed below)
    direct = true
  else
    args = { ... }
  end
  if count % 2 ~= 0 then
    check.fail(('%s: expected x, y pairs, got an odd number of values (%d)'):format(fname, count))
  end
  local xs, ys, n = {}, {}, (count - count % 2) / 2
  for i = 1, n do
    local x, y
    if direct then x, y = select(2 * i - 1, ...) else x, y = args[2 * i - 1], args[2 * i] end
    if not finite(x) then
      check.fail(('%s: x%d must be a finite number, got %s'):format(fname, i, check.describe(x)))
    end
    if not finite(y) then
      check.fail(('%s: y%d must be a finite number, got %s'):format(fname, i, check.describe(y)))
    end
    xs[i], ys[i] = x, y
  end
  return xs, ys, n
end

--- Either both of an optional reference point are given, or neither.
---@param x any
---@param y any
---@param fname string
---@return number|nil, number|nil
function check.optPoint(x, y, fname)
  if x == nil and y == nil then return nil, nil end
  check.number(x, fname, 'reference x')
  check.number(y, fname, 'reference y')
  return x, y
end

return check
