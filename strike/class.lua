--- A tiny class helper with the extension API the Strike README documents:
--- `Base:extend()`, `Class:new(...)` as the constructor body (its return value is ignored),
--- `Class(...)` to instantiate, `Class.super` for the parent, and `obj:is(Class)`.
--- Written for strike; it follows the shape of rxi's classic without its code.

---@class strike.Object
---@field super strike.Object|nil the parent class
local Object = {}
Object.__index = Object

--- Constructor body; subclasses override it. The return value is ignored.
function Object:new() end

--- Create a subclass. Metamethods (keys starting with "__") are copied so that
--- instances of the subclass keep them.
---@return table cls the new class
function Object:extend()
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
  local obj = setmetatable({}, self)
  obj:new(...)
  return obj
end

return Object
