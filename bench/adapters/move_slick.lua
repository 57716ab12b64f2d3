--- slick (erinmaus/slick) for bench/move.lua, through its public API (README, "slick.world"):
--- slick.newWorld(width, height, options) over the square (a margin of 64 px around it, so
--- that its quad tree holds every box from the start), every box an entity at its centre
--- with slick.newRectangleShape(-w / 2, -h / 2, w, h), the mover likewise, moved with
--- world:move(item, goalX, goalY, nil, query) (no filter: slick's default 'slide'; `query` one
--- slick.newWorldQuery(world) reused by every move, the README's way to save garbage) and
--- teleported with world:update(item, x, y). An entity's position is its centre here, so no
--- conversion. The collisions counted are `#query.results` as world:move returns it (slick may
--- list the same pair more than once in one move, README "slick.world").
---
--- slick sets its modules up with setfenv and calls the global unpack, so it loads as is on
--- Lua 5.1 and LuaJIT only. On Lua 5.2+ this adapter loads slick's own files (unchanged) with
--- load(..., env): env is a table over _G that adds unpack = table.unpack and a setfenv that
--- does nothing (slick's init.lua uses it only to give its modules a `require` that prefixes
--- the folder slick was required from, which is empty here), and its own `require` for the
--- slick.* modules (kept in a private table, not package.loaded). Nothing global changes.
---
--- LuaJIT 2.1.0-beta3 (Debian's luajit) crashes (SIGSEGV in compiled code) in some runs of
--- this workload through slick with the JIT on, at random: about one run in three, one in
--- eight with its 'fold' optimisation off, and still with slick's table.clear replaced by its
--- pure-Lua fallback. With the JIT off it runs, and makes the same moves as on Lua 5.1 and
--- 5.4. So A.jitOff: bench/move.lua runs slick with the JIT off on LuaJIT (unless --peer-jit),
--- as bench/adapters/slick.lua does for world:test.
--- Loaded from $STRIKE_PEERS/slick; never committed. Same methods as move_strike.lua.
local A = { name = 'slick', note = 'slick.newWorld(), world:move(item, goalX, goalY, nil, query) with a reused query',
  jitOff = true }

local slick

-- slick on Lua 5.2+: its files loaded with the shims above (see the header).
local function loadShimmed(root)
  local loaded = {}
  local env = setmetatable({ unpack = rawget(table, 'unpack'), setfenv = function() end }, { __index = _G })
  local function req(name)
    if name ~= 'slick' and not name:match('^slick%.') then return require(name) end
    if loaded[name] == nil then
      local rel = name:gsub('%.', '/')
      local path, f = nil, nil
      for _, p in ipairs({ root .. '/' .. rel .. '.lua', root .. '/' .. rel .. '/init.lua' }) do
        f = io.open(p, 'rb')
        if f then path = p break end
      end
      if not f then error('module ' .. name .. ' not found under ' .. root, 2) end
      local src = f:read('*a')
      f:close()
      local chunk = assert(load(src, '@' .. path, 't', env))
      local v = chunk(name, path)
      if v == nil then v = true end
      loaded[name] = v
    end
    return loaded[name]
  end
  env.require = req
  env._G = env
  return req('slick')
end

function A.load(peers, folder)
  local root = peers .. '/' .. folder
  local f = io.open(root .. '/slick/init.lua', 'r')
  if not f then return nil, 'no ' .. root .. '/slick/init.lua' end
  f:close()
  local ok, lib
  if rawget(_G, 'setfenv') then
    package.path = root .. '/?.lua;' .. root .. '/?/init.lua;' .. package.path
    ok, lib = pcall(require, 'slick')
  else
    ok, lib = pcall(loadShimmed, root)
    A.note = A.note .. '; loaded with unpack and setfenv shims (Lua 5.2+)'
  end
  if not ok then return nil, lib end
  if type(lib) ~= 'table' or not lib.newWorld then return nil, 'slick did not load' end
  slick = lib
  A.lib = lib -- (bench/adapters/movers_slick.lua moves with it too)
  return true
end

local MARGIN = 64

function A.new(w)
  local side = w.side
  local world = slick.newWorld(side + 2 * MARGIN, side + 2 * MARGIN, { quadTreeX = -MARGIN, quadTreeY = -MARGIN })
  local x, y, bw, bh = w.x, w.y, w.w, w.h
  for i = 1, w.n do world:add({ i = i }, x[i], y[i], slick.newRectangleShape(-bw[i] / 2, -bh[i] / 2, bw[i], bh[i])) end
  local item = { mover = true }
  world:add(item, w.startX, w.startY, slick.newRectangleShape(-w.mw / 2, -w.mh / 2, w.mw, w.mh))
  local query = slick.newWorldQuery(world)
  local st = { world = world, item = item }
  function st.move(gx, gy)
    local ax, ay, _, n = world:move(item, gx, gy, nil, query)
    return ax, ay, n
  end
  function st.teleport(tx, ty)
    world:update(item, tx, ty)
  end
  return st
end

return A
