--- strike's S.pace through its public API, for bench/space.lua. Two variants: bodies that
--- are single-shape colliders (S.trikers.Rectangle / RegularPolygon / Circle, what a game
--- builds) and bodies that are bare shapes (S.hapes.*), both added to an S.pace().
---
--- Adapter (every space adapter): { name, note,
---   new() -> st                       an empty world
---   make(w, i) -> body                body i of world w (bench/spaceworld.lua), not added
---   add(st, body, i)                  adds it (i: its number, kept for the answers)
---   build(w) -> st                    new() + make + add of every body, in order
---   move(st, w)                       moves every body to w's positions
---   collide(st) -> pairs              the colliding pairs now (a count)
---   bullet(x, y) -> body              a circle of radius 2, not added
---   remove(st, body)
---   ray(st, x, y, dx, dy, len) -> i, distance   the closest hit (body number), or nil
--- }
local S = require('strike')
local SW = require('bench.spaceworld')

local function variant(name, note, ns)
  local Rectangle, RegularPolygon, Circle = ns.Rectangle, ns.RegularPolygon, ns.Circle
  local A = { name = name, note = note }

  function A.new()
    return { space = S.pace(), bodies = {}, index = {}, out = {} }
  end

  function A.make(w, i)
    local k = w.kind[i]
    if k == SW.BOX then return Rectangle(w.x[i], w.y[i], w.w[i], w.h[i]) end
    if k == SW.POLYGON then return RegularPolygon(w.x[i], w.y[i], w.sides[i], w.r[i], w.angle[i]) end
    return Circle(w.x[i], w.y[i], w.r[i])
  end

  function A.add(st, body, i)
    st.space:add(body)
    st.bodies[i], st.index[body] = body, i
  end

  function A.build(w)
    local st = A.new()
    local make, add = A.make, A.add
    for i = 1, w.n do add(st, make(w, i), i) end
    return st
  end

  function A.move(st, w)
    local bodies, x, y = st.bodies, w.x, w.y
    for i = 1, w.n do bodies[i]:translateTo(x[i], y[i]) end
  end

  function A.collide(st)
    local _, n = st.space:collisions(st.out)
    return n
  end

  function A.bullet(x, y)
    return Circle(x, y, 2)
  end

  function A.remove(st, body)
    st.space:remove(body)
    st.index[body] = nil
  end

  function A.ray(st, x, y, dx, dy, len)
    local body, d = st.space:rayCast(x, y, dx, dy, len)
    if body then return st.index[body], d end
    return nil
  end

  return A
end

return {
  colliders = variant('strike', 'S.trikers colliders (Rectangle, RegularPolygon, Circle) in S.pace', S.trikers),
  shapes = variant('strike-shapes', 'bare S.hapes in S.pace', S.hapes),
}
