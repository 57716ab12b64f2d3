--- The built-in shape kinds and their kernels, registered in the operation tables of
--- dispatch.lua:
---   'polygon'   convex polygons and edges (a polygon of two vertices): collide/sat.lua
---   'circle'    circles and points (a circle of radius 0): collide/sat.lua
---   'chain'     one-sided chain segments with ghost vertices: collide/chain.lua
--- Contacts come from collide/contact.lua, rays from collide/ray.lua. Loading this module
--- registers them; strike's init.lua loads it.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local dispatch = require(ROOT .. '.collide.dispatch')
local sat = require(ROOT .. '.collide.sat')
local chain = require(ROOT .. '.collide.chain')
local contact = require(ROOT .. '.collide.contact')
local ray = require(ROOT .. '.collide.ray')

local register = dispatch.register

local cos, sin, pi = math.cos, math.sin, math.pi

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

dispatch.registerKind('polygon', { ray = ray.vertexShape })
dispatch.registerKind('circle', { ray = ray.circle, outline = circleOutline, normals = circleNormals })
dispatch.registerKind('chain', { ray = ray.segment })

register('polygon', 'polygon', { collide = sat.polygonPolygon, contact = contact.polygons })
register('polygon', 'circle', { collide = sat.polygonCircle, contact = contact.polygonCircle })
register('circle', 'circle', { collide = sat.circleCircle, contact = contact.circles })
register('chain', 'polygon', { collide = chain.chainPolygon, contact = contact.polygons })
register('chain', 'circle', { collide = chain.chainCircle, contact = contact.polygonCircle })
register('chain', 'chain', { collide = chain.chainChain, contact = contact.none })

return dispatch
