--- A tiny class helper with the extension API the Strike README documents:
--- `Base:extend()`, `Class:new(...)` as the constructor body (its return value is ignored),
--- `Class(...)` to instantiate, `Class.super` for the parent, and `obj:is(Class)`.
--- Written for strike; it follows the shape of rxi's classic without its code.
local check = require((...):match('^(.-)%.[^%.]+$') .. '.check')
local type = type

---@class strike.Object
---@field super strike.Object|nil the parent class
local Object = {}
Object.__index = Object

--- Constructor body; subclasses override it. The return value is ignored.
function Object:new()
  if type(self) ~= 'table' or getmetatable(self) == nil then check.badSelf(self, 'strike.Object:new') end
end

--- Create a subclass. Metamethods (keys starting with "__") are copied so that
--- instances of the subclass keep them.
---@return table cls the new class
function Object:extend()
  if type(self) ~= 'table' or rawget(self, '__index') ~= self then
    check.badSelf(self, 'strike.Object:extend', 'a class')
  end
  local cls = {}
  for k, v in pairs(self) do
    if type(k) == 'string' and k:sub(1, 2) == '__' then cls[k] = v end
  end
  cls.__index = cls
  cls.super = self
  return setmetatable(cls, self)
end

--- True if `self` (an instance or a class) is `T` or inherits from it.
---@param T table a class
---@return boolean
function Object:is(T)
  -- (obj.is(T) passes the class T as self and nothing as T)
  if type(self) ~= 'table' or (T == nil and rawget(self, '__index') == self) then
    check.badSelf(self, 'strike.Object:is')
  end
  local mt = getmetatable(self)
  while mt do
    if mt == T then return true end
    mt = getmetatable(mt)
  end
  return false
end

--- `Class(...)`: make an instance and run `Class:new(...)` on it.
---@return table instance
function Object:__call(...)
  -- (a class may provide `_alloc(...)`, given the constructor's arguments: the empty table an
  -- instance starts as, with room for the fields it will have; see colliders/Collider.lua)
  local alloc = self._alloc
  local obj = setmetatable(alloc and alloc(...) or {}, self)
  obj:new(...)
  return obj
end

return Object
