--- strike's S.pace:move through its public API, for bench/move.lua. Two variants, as in
--- bench/adapters/space_strike.lua: the boxes as single-shape colliders (S.trikers.Rectangle,
--- what a game builds) and as bare shapes (S.hapes.Rectangle), all added to one S.pace().
---
--- Adapter (every move adapter): { name, note,
---   load(peers, folder) -> true | nil, why   (peers only) finds and loads the library
---   new(w) -> st   the world of bench/move.lua: w.n static boxes (centres w.x, w.y, sizes
---                  w.w, w.h) and the mover (a w.mw x w.mh box centred on w.startX, w.startY),
---                  with st.move(goalX, goalY) -> x, y, collisions (the mover's centre toward
---                  the goal, the default 'slide' response, no filter; the centre it reached
---                  and how many collisions the library reported) and st.teleport(x, y) (the
---                  mover's centre to (x, y), no collision checks).
--- }
local S = require('strike')

local function variant(name, note, ns)
  local Rectangle = ns.Rectangle
  local A = { name = name, note = note }

  function A.new(w)
    local space = S.pace()
    local x, y, bw, bh = w.x, w.y, w.w, w.h
    for i = 1, w.n do space:add(Rectangle(x[i], y[i], bw[i], bh[i])) end
    local body = Rectangle(w.startX, w.startY, w.mw, w.mh)
    space:add(body)
    local st = { space = space, body = body }
    function st.move(gx, gy)
      local ax, ay, _, n = space:move(body, gx, gy)
      return ax, ay, n
    end
    function st.teleport(tx, ty)
      body:translateTo(tx, ty)
    end
    return st
  end

  return A
end

return {
  colliders = variant('strike', 'S.trikers.Rectangle colliders in S.pace(), space:move(body, goalX, goalY)',
    S.trikers),
  shapes = variant('strike-shapes', 'bare S.hapes.Rectangle in S.pace(), space:move(body, goalX, goalY)', S.hapes),
}
