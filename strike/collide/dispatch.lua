--- The one shape-pair dispatch table: dispatch[a.kind][b.kind](a, b, out) fills `out`
--- (an MTV-shaped table) for the pair and returns it. Kinds: 'polygon' (convex polygons
--- and edges), 'circle' and 'chain' (one-sided chain segments with ghost vertices, see
--- collide/chain.lua; two chain segments never collide).
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local sat = require(ROOT .. '.collide.sat')
local chain = require(ROOT .. '.collide.chain')

return {
  polygon = { polygon = sat.polygonPolygon, circle = sat.polygonCircle, chain = chain.polygonChain },
  circle = { polygon = sat.circlePolygon, circle = sat.circleCircle, chain = chain.circleChain },
  chain = { polygon = chain.chainPolygon, circle = chain.chainCircle, chain = chain.chainChain },
}
