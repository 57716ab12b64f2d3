--- The only file that touches names that differ between Lua 5.1, 5.2, 5.3, 5.4 and LuaJIT.
local compat = {}

--- table.unpack on 5.2+, the global unpack on 5.1 and LuaJIT.
compat.unpack = table.unpack or unpack -- luacheck: ignore 113 143

--- math.atan2 on 5.1, 5.2 and LuaJIT; math.atan with two arguments on 5.3+ (5.4 has no atan2).
compat.atan2 = math.atan2 or math.atan -- luacheck: ignore 143

--- LuaJIT's table.new(narray, nhash), a table with room for that many entries, when the VM
--- has it; false elsewhere (PUC Lua sizes a table only from a constructor).
compat.tableNew = (function()
  local ok, new = pcall(require, 'table.new')
  return ok and new or false
end)()

return compat
