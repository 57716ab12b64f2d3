--- The original Strike (Aweptimum/Strike), through its public API: S.hapes.Rectangle /
--- RegularPolygon / Circle / Edge with S.AT(shape1, shape2) → MTV (.separating, :mag()),
--- and S.trikers.Collider(shapes...) with S.triking(c1, c2) → MTV or false.
--- Loaded from $STRIKE_PEERS/Strike; never committed.
---
--- Strike only loads inside LÖVE or on Windows: it lists its own folders with
--- love.filesystem.getDirectoryItems, else `dir /b`. For the load only, this adapter sets a
--- stand-in global `love` whose getDirectoryItems lists a folder's .lua files with `ls`
--- (bench code, not the library), then removes it. Strike also needs lib/DeWallua (a git
--- submodule) for one module, DeWallua's copy of hump.vector-light; when the checkout was
--- made without submodules, a stand-in with the same documented functions is preloaded.
--- DeWallua itself only serves the Concave collider, which the bench never builds.
local A = { name = 'Strike' }

local S -- Strike's API table, once loaded
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

-- hump.vector-light's documented functions that Strike calls (same semantics: normalize
-- leaves a zero vector as it is; perpendicular turns counter-clockwise in y-down).
local function vectorLight()
  local sqrt, cos, sin = math.sqrt, math.cos, math.sin
  local V = {}
  function V.mul(s, x, y) return s * x, s * y end
  function V.div(s, x, y) return x / s, y / s end
  function V.add(x1, y1, x2, y2) return x1 + x2, y1 + y2 end
  function V.sub(x1, y1, x2, y2) return x1 - x2, y1 - y2 end
  function V.dot(x1, y1, x2, y2) return x1 * x2 + y1 * y2 end
  function V.det(x1, y1, x2, y2) return x1 * y2 - y1 * x2 end
  V.cross = V.det
  function V.len2(x, y) return x * x + y * y end
  function V.len(x, y) return sqrt(x * x + y * y) end
  function V.dist2(x1, y1, x2, y2) return (x1 - x2) ^ 2 + (y1 - y2) ^ 2 end
  function V.dist(x1, y1, x2, y2) return sqrt((x1 - x2) ^ 2 + (y1 - y2) ^ 2) end
  function V.normalize(x, y)
    local l = sqrt(x * x + y * y)
    if l > 0 then return x / l, y / l end
    return x, y
  end
  function V.rotate(phi, x, y)
    local c, s = cos(phi), sin(phi)
    return c * x - s * y, s * x + c * y
  end
  function V.perpendicular(x, y) return -y, x end
  function V.project(x, y, u, v)
    local s = (x * u + y * v) / (u * u + v * v)
    return s * u, s * v
  end
  function V.reject(x, y, u, v)
    local px, py = V.project(x, y, u, v)
    return x - px, y - py
  end
  return V
end

local function exists(path)
  local f = io.open(path, 'r')
  if f then f:close() return true end
  return false
end

-- love.filesystem.getDirectoryItems stand-in: the .lua files of a folder, sorted.
local function luaFiles(dir)
  local list = {}
  local p = io.popen('ls -1 "' .. dir .. '" 2>/dev/null')
  if p then
    for name in p:lines() do
      if name:match('%.lua$') then list[#list + 1] = name end
    end
    p:close()
  end
  table.sort(list)
  return list
end

function A.load(peers, folder)
  local root = peers .. '/' .. folder
  if not exists(root .. '/init.lua') then return nil, 'no ' .. root .. '/init.lua' end
  if not io.popen then return nil, 'this VM has no io.popen to list Strike\'s folders' end
  -- Strike requires itself by the folder's name; the benchmark expects the folder `Strike`.
  package.path = peers .. '/?.lua;' .. peers .. '/?/init.lua;' .. package.path
  -- Strike calls the global unpack and math.atan2, which Lua 5.2+ dropped; this process only.
  rawset(_G, 'unpack', rawget(_G, 'unpack') or table.unpack) -- luacheck: ignore 143
  rawset(math, 'atan2', math.atan2 or function(y, x) return math.atan(y, x) end) -- luacheck: ignore 143
  if not exists(root .. '/lib/DeWallua/vector-light.lua') then
    package.preload[folder .. '.lib.DeWallua.vector-light'] = vectorLight
  end
  local hadLove = rawget(_G, 'love')
  if not hadLove then
    rawset(_G, 'love', { filesystem = { getDirectoryItems = luaFiles } })
  end
  local ok, lib = pcall(require, folder)
  if not hadLove then rawset(_G, 'love', nil) end
  if not ok then return nil, lib end
  if type(lib) ~= 'table' or not lib.AT or not lib.hapes then return nil, 'Strike loaded without its API' end
  S = lib
  return true
end

local function shape(d)
  local H = S.hapes
  if d.kind == 'rect' then return H.Rectangle(d.x, d.y, d.w, d.h, d.angle) end
  if d.kind == 'ngon' then return H.RegularPolygon(d.x, d.y, d.n, d.r, d.angle) end
  if d.kind == 'circle' then return H.Circle(d.x, d.y, d.r) end
  if d.kind == 'edge' then return H.Edge(d.x1, d.y1, d.x2, d.y2) end
  return nil
end

local function collider(d)
  if d.kind == 'compound' then
    local list = {}
    for i, p in ipairs(d.parts) do list[i] = shape(p) end
    return S.trikers.Collider(unpack(list))
  end
  return S.trikers.Collider(shape(d))
end

A.methods = {
  {
    name = 'S.AT',
    build = shape,
    test = function(a, b)
      local m = S.AT(a, b)
      if m.separating then return false, 0 end
      return true, m:mag()
    end,
  },
  {
    name = 'S.triking',
    build = collider,
    test = function(a, b)
      local m = S.triking(a, b)
      if not m then return false, 0 end
      return true, m:mag()
    end,
  },
}

A.transform = {
  build = shape,
  step = function(s)
    s:translate(0.5, -0.25)
    s:rotate(0.01)
    return s:getBbox()
  end,
}

return A
