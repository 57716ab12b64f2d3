--- LÖVE debug drawing: the only file of strike that reads `love`. It is loaded on the
--- first draw call, so strike itself loads and runs without LÖVE. Every function draws
--- with love.graphics as it finds it, restores the colour it found, and allocates nothing
--- per call.
local ROOT = (...):match('^(.-)%.[^%.]+$')
local check = require(ROOT .. '.check')
local kinds = require(ROOT .. '.collide.dispatch').kind
local reserved = require(ROOT .. '.reserved')

local draw = {}
local scratch = {}

-- love.graphics, or an error at the caller's line when LÖVE is not there.
local function graphics(fname)
  local love = rawget(_G, 'love')
  local g = type(love) == 'table' and love.graphics
  if not g then check.fail(fname .. ': drawing needs LÖVE (love.graphics is not available)') end
  return g
end

-- (a collider has its leaf cache `_single`; a shape its pose stamp and a registered kind)
local function isBody(v)
  return type(v) == 'table' and (v._shapes ~= nil and v._single ~= nil or v._pose ~= nil and kinds[v._kind] ~= nil)
end

local function checkBody(fname, v)
  if not isBody(v) then
    reserved.check(fname, 'argument 1', v)
    check.fail(('%s: argument 1 must be a strike shape or collider, got %s'):format(fname, check.describe(v)))
  end
end

local function checkMTV(fname, mtv)
  if type(mtv) ~= 'table' or type(mtv.x) ~= 'number' or type(mtv.y) ~= 'number' then
    check.fail(('%s: argument 1 must be an MTV, got %s'):format(fname, check.describe(mtv)))
  end
end

-- Apply fn(g, shape, a, b) to every leaf of a shape or collider.
local function eachLeaf(g, body, fn, a, b)
  if body._shapes then
    for s in body:elems() do fn(g, s, a, b) end
  else
    fn(g, body, a, b)
  end
end

-- Run fn(g, a, b, c) in colour (r, gr, b) and restore the colour found.
local function inColour(g, r, gr, bl, fn, a, b, c)
  local r0, g0, b0, a0 = g.getColor()
  g.setColor(r, gr, bl, 1)
  fn(g, a, b, c)
  g.setColor(r0, g0, b0, a0)
end

-- A shape's outline: its kind's own (dispatch.kind[kind].outline), or its vertices.
local function outline(g, s, mode)
  local kind = kinds[s._kind]
  if not kind then reserved.badKind('strike:draw', s) end
  local own = kind.outline
  if own then return own(g, s, mode) end
  local v, n = s:getVertices(scratch)
  if n == 2 then g.line(v[1], v[2], v[3], v[4]) else g.polygon(mode, v) end
end

--- Draw a shape, or every leaf of a collider, in the current colour.
---@param body table a shape or collider
---@param mode string|nil 'line' (default) or 'fill'
function draw.body(body, mode)
  local g = graphics('strike:draw')
  if mode == nil then mode = 'line' end
  if mode ~= 'line' and mode ~= 'fill' then
    check.fail(("strike:draw: mode must be 'line' or 'fill', got %s"):format(check.describe(mode)))
  end
  eachLeaf(g, body, outline, mode)
end

local function mtvLines(g, mtv)
  local ax, ay = mtv.colliderShape:getCentroid()
  local bx, by = mtv.collidedShape:getCentroid()
  g.line(ax, ay, bx, by)
  g.line(ax, ay, ax + mtv.x, ay + mtv.y)
end

--- Draw a colliding MTV (red): the line between the two shapes' centroids, and the
--- vector from the first one's centroid. Nothing for a separating MTV.
---@param mtv strike.MTV
function draw.mtv(mtv)
  local g = graphics('strike.howMTV')
  checkMTV('strike.howMTV', mtv)
  if mtv.separating then return end
  inColour(g, 1, 0.2, 0.2, mtvLines, mtv)
end

-- A shape's normals: its kind's own (dispatch.kind[kind].normals), or one per edge.
local function shapeNormals(g, s, len)
  local kind = kinds[s._kind]
  if not kind then reserved.badKind('strike.howNorms', s) end
  local own = kind.normals
  if own then return own(g, s, len) end
  for i, x1, y1, x2, y2 in s:ipairs() do
    local nx, ny = s:getNormal(i)
    local mx, my = (x1 + x2) / 2, (y1 + y2) / 2
    g.line(mx, my, mx + nx * len, my + ny * len)
  end
end

local function normals(g, body, len) eachLeaf(g, body, shapeNormals, len) end

--- Draw outward normals (cyan), `len` long (default 15): at each edge's midpoint, and
--- eight around each circle.
---@param body table a shape or collider
---@param len number|nil
function draw.normals(body, len)
  local g = graphics('strike.howNorms')
  checkBody('strike.howNorms', body)
  len = check.optNumber(len, 'strike.howNorms', 'length', 15)
  inColour(g, 0.2, 0.9, 0.9, normals, body, len)
end

-- The projection of shape s on the MTV's axis, drawn as a segment on the axis line
-- through (ox, oy), shifted sideways by `side`.
local function projection(g, s, mtv, side)
  local nx, ny = mtv.nx, mtv.ny
  local ox, oy = mtv.colliderShape:getCentroid()
  local lo, hi = s:project(nx, ny)
  local o = nx * ox + ny * oy
  local px, py = -ny * side, nx * side
  g.line(ox + nx * (lo - o) + px, oy + ny * (lo - o) + py, ox + nx * (hi - o) + px, oy + ny * (hi - o) + py)
end

local function projections(g, mtv)
  projection(g, mtv.colliderShape, mtv, 4)
  projection(g, mtv.collidedShape, mtv, 8)
end

--- Draw both shapes' projections on the MTV's axis (yellow), side by side along the
--- axis line through the first shape's centroid: where they overlap is the depth.
---@param mtv strike.MTV
function draw.projections(mtv)
  local g = graphics('strike.howProj')
  checkMTV('strike.howProj', mtv)
  if type(mtv.colliderShape) ~= 'table' or type(mtv.collidedShape) ~= 'table' then
    check.fail('strike.howProj: the MTV must come from S.AT or S.triking')
  end
  inColour(g, 1, 0.9, 0.2, projections, mtv)
end

local function contactMarks(g, contacts, len)
  for i = 1, contacts.count do
    local p = contacts[i]
    local nx, ny = p.nx or contacts.nx, p.ny or contacts.ny -- (a compound's points: each its pair's)
    g.circle('fill', p.x, p.y, 3)
    g.line(p.x, p.y, p.x + nx * len, p.y + ny * len)
  end
end

--- Draw contact points from S.ite (green dots) with the normal, `len` long (default 15).
---@param contacts table|nil the result of S.ite (nil draws nothing)
---@param len number|nil
function draw.contacts(contacts, len)
  local g = graphics('strike.howContacts')
  if contacts == nil then return end
  if type(contacts) ~= 'table' or type(contacts.count) ~= 'number' then
    check.fail(('strike.howContacts: argument 1 must be the result of S.ite, got %s'):format(
      check.describe(contacts)))
  end
  len = check.optNumber(len, 'strike.howContacts', 'length', 15)
  inColour(g, 0.3, 1, 0.3, contactMarks, contacts, len)
end

local function rayMarks(g, body, x, y, dx, dy, maxDistance)
  local t, hx, hy, nx, ny = body:rayCast(x, y, dx, dy, maxDistance)
  local l = (dx * dx + dy * dy) ^ 0.5
  if t then
    g.line(x, y, hx, hy)
    g.circle('fill', hx, hy, 3)
    g.line(hx, hy, hx + nx * 15, hy + ny * 15)
  else
    local reach = maxDistance or 1e4
    g.line(x, y, x + dx / l * reach, y + dy / l * reach)
  end
end

--- Cast a ray at a shape or collider and draw it (magenta): up to the first hit, the hit
--- point and its normal; or the whole ray (up to maxDistance, else 10,000 units) on a miss.
---@param body table
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number|nil
---@return number|nil distance the hit's distance, as body:rayCast gives it
function draw.ray(body, x, y, dx, dy, maxDistance)
  local g = graphics('strike.howRay')
  checkBody('strike.howRay', body)
  local t = body:rayCast(x, y, dx, dy, maxDistance) -- validates the ray, at the caller's line
  local r0, g0, b0, a0 = g.getColor()
  g.setColor(1, 0.3, 1, 1)
  rayMarks(g, body, x, y, dx, dy, maxDistance)
  g.setColor(r0, g0, b0, a0)
  return t
end

local function nodeBox(g, x0, y0, x1, y1, _, leaf)
  if leaf then g.setColor(0.35, 0.8, 1, 0.5) else g.setColor(0.35, 0.8, 1, 0.18) end
  g.rectangle('line', x0, y0, x1 - x0, y1 - y0)
end

local listed = {} -- (the bodies of a space being drawn)

local function spaceBodies(g, space, list)
  local _, n = space:bodies(list)
  for i = 1, n do eachLeaf(g, list[i], outline, 'line') end
  for i = 1, n do list[i] = nil end
end

--- Draw a space: every body in the current colour, then the broadphase's boxes (light blue:
--- the bodies' fat boxes brighter, the tree's inner boxes fainter).
---@param space table
function draw.space(space)
  local g = graphics('strike.howSpace')
  if type(space) ~= 'table' or space._type ~= 'space' or getmetatable(space) == nil then
    check.fail(('strike.howSpace: argument 1 must be a space (S.pace()), got %s'):format(check.what(space)))
  end
  spaceBodies(g, space, listed)
  local r0, g0, b0, a0 = g.getColor()
  space:_eachNode(nodeBox, g)
  g.setColor(r0, g0, b0, a0)
end

return draw
