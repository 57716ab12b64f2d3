--- The only file that touches names that differ between Lua 5.1, 5.2, 5.3, 5.4 and LuaJIT.
local compat = {}

--- table.unpack on 5.2+, the global unpack on 5.1 and LuaJIT.
compat.unpack = table.unpack or unpack -- luacheck: ignore 113 143

--- math.atan with two arguments on 5.3+, math.atan2 before.
local atan, atan2 = math.atan, math.atan2 -- luacheck: ignore 143
if atan2 then
  compat.atan2 = atan2
else
  compat.atan2 = function(y, x) return atan(y, x) end
end

return compat
