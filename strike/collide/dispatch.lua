--- The one shape-pair dispatch table: dispatch[a.kind][b.kind](a, b, out) fills `out`
--- (an MTV-shaped table) for the pair and returns it. Kinds: 'polygon' (convex polygons
--- and edges) and 'circle'.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local sat = require(ROOT .. '.collide.sat')

return {
  polygon = { polygon = sat.polygonPolygon, circle = sat.polygonCircle },
  circle = { polygon = sat.circlePolygon, circle = sat.circleCircle },
}
