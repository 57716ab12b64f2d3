--- strike for bench/movers.lua, through its public API: one S.pace(), the walls as
--- S.trikers.Rectangle, the movers as S.trikers.Rectangle (boxes) and S.trikers.Capsule (w wide,
--- h tall, caps included), each moved with space:move(body, goalX, goalY) (no filter: 'slide').
---
--- Adapter (every movers adapter): { name, note, jitOff?,
---   load(peers, folder) -> true | nil, why   (peers only) finds and loads the library
---   new(w) -> st   the world of bench/movers.lua (w.n movers: centres w.x, w.y, sizes w.w, w.h,
---                  w.capsule[i]; walls: centres w.wx, w.wy, sizes w.ww, w.wh), with
---                  st.move(i, goalX, goalY) -> x, y, collisions (mover i's centre toward the
---                  goal, the default 'slide' response; the centre it reached and how many
---                  collisions the library reported).
--- }
local S = require('strike')

local A = { name = 'strike', note = 'S.trikers.Rectangle and S.trikers.Capsule in S.pace(), space:move(body, goalX, '
  .. 'goalY)' }

function A.new(w)
  local space = S.pace()
  local Rectangle, Capsule = S.trikers.Rectangle, S.trikers.Capsule
  for k = 1, #w.wx do space:add(Rectangle(w.wx[k], w.wy[k], w.ww[k], w.wh[k])) end
  local bodies = {}
  for i = 1, w.n do
    local make = w.capsule[i] and Capsule or Rectangle
    bodies[i] = space:add(make(w.x[i], w.y[i], w.w[i], w.h[i]))
  end
  local move = space.move
  return {
    move = function(i, gx, gy)
      local ax, ay, _, n = move(space, bodies[i], gx, gy)
      return ax, ay, n
    end,
  }
end

return A
