--- bump.lua (kikito/bump.lua) for bench/move.lua, through its public API: bump.newWorld()
--- (its default 64 px cells), every box added with world:add at its top-left corner, the
--- mover moved with world:move(item, goalX, goalY) (no filter: bump's default 'slide') and
--- teleported with world:update. bump speaks in top-left corners: the bench's centres are
--- turned into corners (centre - size / 2) on the way in and back on the way out.
--- bump's world:move builds a new list of collisions (and its records) on every call: it
--- has nothing to reuse. Loaded from $STRIKE_PEERS/bump.lua; never committed. Same methods as
--- move_strike.lua.
local A = { name = 'bump', note = 'bump.newWorld() (64 px cells), world:move(item, goalX, goalY) (AABBs only)' }

local bump

function A.load(peers, folder)
  local path = peers .. '/' .. folder .. '/bump.lua'
  local chunk, err = loadfile(path)
  if not chunk then return nil, err end
  local ok, lib = pcall(chunk, 'bump')
  if not ok then return nil, lib end
  if type(lib) ~= 'table' or not lib.newWorld then return nil, path .. ' did not return bump' end
  bump = lib
  A.lib = lib -- (bench/adapters/movers_bump.lua moves with it too)
  return true
end

function A.new(w)
  local world = bump.newWorld()
  local x, y, bw, bh = w.x, w.y, w.w, w.h
  for i = 1, w.n do world:add({ i = i }, x[i] - bw[i] / 2, y[i] - bh[i] / 2, bw[i], bh[i]) end
  local hw, hh = w.mw / 2, w.mh / 2
  local item = { mover = true }
  world:add(item, w.startX - hw, w.startY - hh, w.mw, w.mh)
  local st = { world = world, item = item }
  function st.move(gx, gy)
    local ax, ay, _, n = world:move(item, gx - hw, gy - hh)
    return ax + hw, ay + hh, n
  end
  function st.teleport(tx, ty)
    world:update(item, tx - hw, ty - hh)
  end
  return st
end

return A
