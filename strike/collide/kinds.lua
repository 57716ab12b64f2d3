--- The built-in shape kinds and their kernels, registered in the operation tables of
--- dispatch.lua:
---   'polygon'   convex polygons and edges (a polygon of two vertices): collide/sat.lua
---   'circle'    circles and points (a circle of radius 0): collide/sat.lua
---   'chain'     one-sided chain segments with ghost vertices: collide/chain.lua
---   'rounded'   a core polygon or segment with a radius (capsules, rounded rectangles and
---               polygons): collide/rounded.lua; against circles, sat.lua's polygon-circle
---               test with the two radii added
--- Contacts come from collide/contact.lua, rays from collide/ray.lua. Loading this module
--- registers them; strike's init.lua loads it.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local dispatch = require(ROOT .. '.collide.dispatch')
local sat = require(ROOT .. '.collide.sat')
local chain = require(ROOT .. '.collide.chain')
local contact = require(ROOT .. '.collide.contact')
local ray = require(ROOT .. '.collide.ray')
local rounded = require(ROOT .. '.collide.rounded')

local register = dispatch.register

local cos, sin, pi = math.cos, math.sin, math.pi
local atan2 = require(ROOT .. '.compat').atan2

-- Drawing a circle (strike/draw.lua calls these with love.graphics): the circle, or a
-- point for radius 0; eight normals around it.
local function circleOutline(g, s, mode)
  local x, y = s:getCentroid()
  local r = s:getRadius()
  if r > 0 then g.circle(mode, x, y, r) else g.points(x, y) end
end

local function circleNormals(g, s, len)
  local x, y = s:getCentroid()
  local r = s:getRadius()
  for k = 0, 7 do
    local nx, ny = cos(k * pi / 4), sin(k * pi / 4)
    g.line(x + nx * r, y + ny * r, x + nx * (r + len), y + ny * (r + len))
  end
end

-- Drawing a rounded shape: the core's faces moved out by the radius, joined by arcs about
-- the core's vertices, each from the normal of the face before to the normal of the face
-- after (the turn at that corner); filled as the core, a strip along each face and a pie
-- slice at each corner, which tile the shape.
local function roundedOutline(g, s, mode)
  local r, n = s:getRounding(), s:getVertexCount()
  local px, py = s:getNormal(n)
  for i = 1, n do
    local x1, y1, x2, y2 = s:getEdge(i)
    local nx, ny = s:getNormal(i)
    local a1 = atan2(py, px)
    local turn = atan2(px * ny - py * nx, px * nx + py * ny)
    if turn < 0 then turn = turn + 2 * pi end
    if n == 2 then turn = pi end
    if mode == 'fill' then
      g.arc('fill', 'pie', x1, y1, r, a1, a1 + turn)
      if x1 ~= x2 or y1 ~= y2 then
        g.polygon('fill', x1, y1, x2, y2, x2 + nx * r, y2 + ny * r, x1 + nx * r, y1 + ny * r)
      end
    else
      g.arc('line', 'open', x1, y1, r, a1, a1 + turn)
      if x1 ~= x2 or y1 ~= y2 then g.line(x1 + nx * r, y1 + ny * r, x2 + nx * r, y2 + ny * r) end
    end
    px, py = nx, ny
  end
  if mode == 'fill' and n >= 3 then g.polygon('fill', (s:getVertices())) end -- (the table alone)
end

local function roundedNormals(g, s, len)
  local r = s:getRounding()
  for i = 1, s:getVertexCount() do
    local x1, y1, x2, y2 = s:getEdge(i)
    local nx, ny = s:getNormal(i)
    local mx, my = (x1 + x2) / 2 + nx * r, (y1 + y2) / 2 + ny * r
    g.line(mx, my, mx + nx * len, my + ny * len)
  end
end

dispatch.registerKind('polygon', { ray = ray.vertexShape })
dispatch.registerKind('rounded', { ray = ray.rounded, outline = roundedOutline, normals = roundedNormals })
dispatch.registerKind('circle', { ray = ray.circle, outline = circleOutline, normals = circleNormals })
dispatch.registerKind('chain', { ray = ray.segment })

register('polygon', 'polygon', { collide = sat.polygonPolygon, contact = contact.polygons })
register('polygon', 'circle', { collide = sat.polygonCircle, contact = contact.polygonCircle })
register('circle', 'circle', { collide = sat.circleCircle, contact = contact.circles })
register('chain', 'polygon', { collide = chain.chainPolygon, contact = contact.polygons })
register('chain', 'circle', { collide = chain.chainCircle, contact = contact.polygonCircle })
register('chain', 'chain', { collide = chain.chainChain, contact = contact.none })
register('rounded', 'rounded', { collide = rounded.collide, contact = contact.rounded })
register('rounded', 'polygon', { collide = rounded.collide, contact = contact.rounded })
register('rounded', 'circle', { collide = sat.polygonCircle, contact = contact.polygonCircle })
register('chain', 'rounded', { collide = chain.chainRounded, contact = contact.rounded })

return dispatch
