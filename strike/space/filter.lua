--- Layers, masks and groups of S.pace (strike/space/Space.lua), without a bit library (Lua
--- 5.1 has none): a body's layer is a name, its mask a set of names (a table name -> true),
--- interned so that bodies with the same mask share one table; "a's layer is in b's mask" is
--- one table lookup. Any number of layers. The rule is Box2D's (b2ShouldCollide, E. Catto):
--- a shared non-zero group decides alone (positive: always, negative: never), else each
--- body's layer must be in the other's mask.
local ROOT = (...):match('^(.-)%.space%.[^%.]+$')
local check = require(ROOT .. '.check')

local describe, fail, type = check.describe, check.fail, type

local filter = {}

--- The layer of a body added without one.
filter.DEFAULT = 'default'

-- Interned masks: canonical key (the sorted names, joined by NUL) -> set. Shared by every
-- space; a mask is never changed once made.
local interned = setmetatable({}, { __mode = 'v' })

--- The set for a list of layer names (validated: a list of strings; duplicates are fine).
--- `fname` names the function for errors.
---@param names any
---@param fname string
---@return table<string, boolean>
function filter.maskSet(names, fname)
  if type(names) ~= 'table' or getmetatable(names) ~= nil then
    fail(('%s: mask must be a list of layer names, got %s'):format(fname, check.what(names)))
  end
  local n = #names
  local sorted = {}
  for i = 1, n do
    local v = names[i]
    if type(v) ~= 'string' then
      fail(('%s: mask[%d] must be a layer name (a string), got %s'):format(fname, i, describe(v)))
    end
    sorted[i] = v
  end
  for k in pairs(names) do
    if type(k) ~= 'number' or k < 1 or k > n or k % 1 ~= 0 then
      fail(('%s: mask must be a list of layer names, got the key %s'):format(fname, describe(k)))
    end
  end
  table.sort(sorted)
  local key = table.concat(sorted, '\0')
  local set = interned[key]
  if not set then
    set = {}
    for i = 1, n do set[sorted[i]] = true end
    interned[key] = set
  end
  return set
end

--- Can bodies with these layers, masks (sets, or false for every layer) and groups collide?
---@param la string
---@param ma table<string, boolean>|false
---@param ga number
---@param lb string
---@param mb table<string, boolean>|false
---@param gb number
---@return boolean
function filter.pair(la, ma, ga, lb, mb, gb)
  if ga == gb and ga ~= 0 then return ga > 0 end
  return (not ma or ma[lb] == true) and (not mb or mb[la] == true)
end

--- Raise an error at the caller's line unless `f` is a query filter: nil, a function
--- `(body) -> boolean`, or a table `{mask = {names...}}`.
---@param f any
---@param fname string
---@param i integer the argument's position, for the message
function filter.checkQuery(f, fname, i)
  if f == nil or type(f) == 'function' then return end
  if type(f) == 'table' and getmetatable(f) == nil then
    local m = f.mask
    if type(m) == 'table' then
      for j = 1, #m do
        if type(m[j]) ~= 'string' then
          fail(('%s: argument %d (filter): mask[%d] must be a layer name (a string), got %s'):format(fname, i, j,
            describe(m[j])))
        end
      end
      return
    end
    if m ~= nil then
      fail(('%s: argument %d (filter): mask must be a list of layer names such as {%s}, got %s'):format(fname, i,
        type(m) == 'string' and ('%q'):format(m) or "'wall'", describe(m)))
    end
    local key = next(f)
    if key ~= nil then
      fail(('%s: argument %d (filter): a layer filter is {mask = {layer names}}, got a table with the key %s and no'
        .. ' mask'):format(fname, i, type(key) == 'string' and ('%q'):format(key) or describe(key)))
    end
    fail(('%s: argument %d (filter): a layer filter is {mask = {layer names}}, got an empty table'):format(fname, i))
  end
  fail(('%s: argument %d (filter) must be nil, a function (body) -> boolean or a table {mask = {layer names}},'
    .. ' got %s'):format(fname, i, type(f) == 'table' and getmetatable(f) ~= nil and check.what(f) == 'table'
    and 'a table with a metatable' or check.what(f)))
end

--- Does the query filter `f` (checked) let a body on layer `layer` through?
---@param f nil|function|table
---@param body table
---@param layer string
---@return boolean
function filter.query(f, body, layer)
  if f == nil then return true end
  if type(f) == 'function' then return f(body) and true or false end
  local m = f.mask
  for j = 1, #m do
    if m[j] == layer then return true end
  end
  return false
end

return filter
