--- bump.lua (kikito/bump.lua) as a world, for bench/space.lua, through its public API:
--- bump.newWorld() (its default 64 px cells), items added with world:add, moved with
--- world:update, and world:queryRect per body on the body's own rectangle (each pair is
--- found from both sides and every body finds itself: the pair count is the sum of
--- (len - 1), halved). bump knows only axis-aligned rectangles: every body is its bounding
--- box (a polygon's and a circle's too), so its answers are about boxes, not shapes.
--- Rays: world:querySegmentWithCoords, first item (boxes again).
--- Loaded from $STRIKE_PEERS/bump.lua; never committed. Same methods as space_strike.lua.
local A = { name = 'bump', note = 'bump.newWorld(), update + queryRect per body (bounding boxes only)' }

local bump

function A.load(peers, folder)
  local path = peers .. '/' .. folder .. '/bump.lua'
  local chunk, err = loadfile(path)
  if not chunk then return nil, err end
  local ok, lib = pcall(chunk, 'bump')
  if not ok then return nil, lib end
  if type(lib) ~= 'table' or not lib.newWorld then return nil, path .. ' did not return bump' end
  bump = lib
  return true
end

function A.new()
  return { world = bump.newWorld(), bodies = {}, index = {} }
end

-- An item: its half-sizes and the corner it is added at.
function A.make(w, i)
  local hw, hh = w.hw[i], w.hh[i]
  return { hw = hw, hh = hh, x = w.x[i] - hw, y = w.y[i] - hh }
end

function A.add(st, item, i)
  st.world:add(item, item.x, item.y, 2 * item.hw, 2 * item.hh)
  st.bodies[i], st.index[item] = item, i
end

function A.build(w)
  local st = A.new()
  for i = 1, w.n do A.add(st, A.make(w, i), i) end
  return st
end

function A.move(st, w)
  local world, bodies, x, y = st.world, st.bodies, w.x, w.y
  for i = 1, w.n do
    local item = bodies[i]
    world:update(item, x[i] - item.hw, y[i] - item.hh)
  end
end

function A.collide(st)
  local world, bodies, count = st.world, st.bodies, 0
  for i = 1, #bodies do
    local x, y, w, h = world:getRect(bodies[i])
    local _, len = world:queryRect(x, y, w, h)
    count = count + len - 1
  end
  return count / 2
end

function A.bullet(x, y)
  return { hw = 2, hh = 2, x = x - 2, y = y - 2 }
end

function A.remove(st, item)
  st.world:remove(item)
  st.index[item] = nil
end

function A.ray(st, x, y, dx, dy, len)
  local info, n = st.world:querySegmentWithCoords(x, y, x + dx * len, y + dy * len)
  if n == 0 then return nil end
  return st.index[info[1].item], math.max(0, info[1].ti1) * len
end

return A
