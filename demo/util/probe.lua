--- The probe model: a painter (same methods as util/lovepaint.lua) that records the
--- geometry of what a scene draws instead of drawing it, then picks screenshot probes from
--- it: pixels well inside a filled shape, or of plain background, far from every line,
--- dot, overlay and later fill. Pure Lua.
---
--- Each probe is { x =, y =, r =, g =, b =, what = } with integer pixel coordinates
--- (0-based, as in an image); the geometry is evaluated at the pixel's centre.
local geom = require((...):match('^(.-)[^%.]+$') .. 'geom')

local sqrt, huge, floor, min, max = math.sqrt, math.huge, math.floor, math.min, math.max
local cos, sin, pi = math.cos, math.sin, math.pi
local segmentDistance = geom.segmentDistance

local probe = {}

--- Clearance a probe needs from every edge and mark, in pixels: 4, and one more for the half
--- pixel between a pixel's centre and its corner, and for antialiasing.
probe.MARGIN = 5
-- Clearance beyond which all candidates count as equally good (keeps the search short).
local CAP = 12

local Model = {}
Model.__index = Model

--- An empty model of a w x h screen.
---@param w number @param h number
function probe.model(w, h)
  return setmetatable({ w = w, h = h, fills = {}, marks = {} }, Model)
end

-- Marks: things drawn on top whose pixels a probe must avoid. Each has a bounding box
-- (minx, miny, maxx, maxy) and a distance function; `r` is its half thickness.
local function addMark(self, m)
  self.marks[#self.marks + 1] = m
  return m
end

local function segment(self, x1, y1, x2, y2, r)
  return addMark(self, { kind = 'seg', x1 = x1, y1 = y1, x2 = x2, y2 = y2, r = r,
    minx = min(x1, x2) - r, miny = min(y1, y2) - r, maxx = max(x1, x2) + r, maxy = max(y1, y2) + r })
end

local function disc(self, x, y, r)
  return addMark(self, { kind = 'disc', x = x, y = y, r = r, minx = x - r, miny = y - r, maxx = x + r, maxy = y + r })
end

local function ring(self, x, y, radius, r)
  local e = radius + r
  return addMark(self, { kind = 'ring', x = x, y = y, radius = radius, r = r,
    minx = x - e, miny = y - e, maxx = x + e, maxy = y + e })
end

-- A rounded shape's core: its vertices (x1, y1, ...), their count and, for a core with
-- an area, its faces as (nx, ny, c) with n . p <= c inside.
local function coreOf(s)
  local core, n = {}, s:getVertexCount()
  for i = 1, n do core[2 * i - 1], core[2 * i] = s:getVertex(i) end
  local faces
  if n >= 3 then
    faces = {}
    for i, x1, y1 in s:ipairs() do
      local nx, ny = s:getNormal(i)
      faces[i] = { nx, ny, nx * x1 + ny * y1 }
    end
  end
  return core, n, faces
end

-- Distance from a point to a rounded shape's core (a point, a segment or a convex polygon;
-- negative inside a polygon): exact, so that its rounding minus it is the distance to the
-- shape's boundary as strike draws it (the core's faces moved out, joined by arcs).
local function coreDistance(core, n, faces, px, py)
  if n == 1 then return sqrt((px - core[1]) ^ 2 + (py - core[2]) ^ 2) end
  local best = huge
  for i = 1, n == 2 and 1 or n do
    local j = i % n + 1
    local d = segmentDistance(px, py, core[2 * i - 1], core[2 * i], core[2 * j - 1], core[2 * j])
    if d < best then best = d end
  end
  if faces then
    for i = 1, #faces do
      local f = faces[i]
      if f[1] * px + f[2] * py > f[3] then return best end
    end
    return -best
  end
  return best
end

-- A rounded shape's outline (arcs about its core's vertices, joined by its faces moved out),
-- r its half thickness.
local function roundedLine(self, s, r)
  local core, n, faces = coreOf(s)
  local minx, miny, maxx, maxy = s:getBounds()
  return addMark(self, { kind = 'rounded', core = core, n = n, faces = faces, radius = s:getRounding(), r = r,
    minx = minx - r, miny = miny - r, maxx = maxx + r, maxy = maxy + r })
end

--- Keep probes out of a rectangle (an overlay panel, text).
function Model:reserve(x, y, w, h)
  return addMark(self, { kind = 'rect', minx = x, miny = y, maxx = x + w, maxy = y + h })
end

-- Distance from a point to a mark's drawn pixels (negative inside).
local function markDistance(m, px, py)
  local k = m.kind
  if k == 'seg' then return segmentDistance(px, py, m.x1, m.y1, m.x2, m.y2) - m.r end
  if k == 'disc' then return sqrt((px - m.x) ^ 2 + (py - m.y) ^ 2) - m.r end
  if k == 'ring' then return math.abs(sqrt((px - m.x) ^ 2 + (py - m.y) ^ 2) - m.radius) - m.r end
  if k == 'rounded' then return math.abs(coreDistance(m.core, m.n, m.faces, px, py) - m.radius) - m.r end
  -- rect: distance outside, negative inside
  local dx = max(m.minx - px, px - m.maxx)
  local dy = max(m.miny - py, py - m.maxy)
  if dx <= 0 and dy <= 0 then return max(dx, dy) end
  return sqrt(max(dx, 0) ^ 2 + max(dy, 0) ^ 2)
end

local function eachLeaf(body, fn)
  if body.getShapeCount then
    for s in body:elems() do fn(s) end
  else
    fn(body)
  end
end

-- A fill's signed distance data: a circle's centre and radius, a rounded shape's core and
-- rounding (a capsule: a segment), or a convex polygon's faces as (nx, ny, c) with
-- n . p <= c inside.
local function fillRecord(s, rgb, label, order)
  local f = { rgb = rgb, label = label, order = order, shape = s }
  f.minx, f.miny, f.maxx, f.maxy = s:getBounds()
  if s:getKind() == 'rounded' then
    f.core, f.n, f.coreFaces = coreOf(s)
    f.rounding = s:getRounding()
  elseif s:getKind() == 'circle' then
    f.cx, f.cy = s:getCentroid()
    f.radius = s:getRadius()
  else
    local faces = {}
    for i, x1, y1 in s:ipairs() do
      local nx, ny = s:getNormal(i)
      faces[#faces + 1] = { nx, ny, nx * x1 + ny * y1 }
    end
    f.faces = faces
  end
  return f
end

--- Signed distance from a point to a fill's boundary: > 0 inside. Outside, it is a lower
--- bound of the distance (the largest face separation), which is what keeping clear needs.
local function fillDistance(f, px, py)
  if f.rounding then return f.rounding - coreDistance(f.core, f.n, f.coreFaces, px, py) end
  if f.radius then return f.radius - sqrt((px - f.cx) ^ 2 + (py - f.cy) ^ 2) end
  local worst = -huge
  for i = 1, #f.faces do
    local face = f.faces[i]
    local d = face[1] * px + face[2] * py - face[3]
    if d > worst then worst = d end
  end
  return -worst
end

--- Painter method: fill a body. Edges become 3-px lines, points dots; areas (rounded shapes
--- such as capsules included) become fills.
function Model:fill(body, rgb, label)
  eachLeaf(body, function(s)
    if s:getKind() == 'rounded' then
      self.fills[#self.fills + 1] = fillRecord(s, rgb, label, #self.fills + 1)
    elseif s:getKind() == 'circle' and s:getRadius() == 0 then
      local x, y = s:getCentroid()
      disc(self, x, y, 2)
    elseif s:getKind() ~= 'circle' and s:getVertexCount() == 2 then
      local x1, y1, x2, y2 = s:getEdge(1)
      segment(self, x1, y1, x2, y2, 2)
    else
      self.fills[#self.fills + 1] = fillRecord(s, rgb, label, #self.fills + 1)
    end
  end)
end

--- Painter method: outline a body (1 px).
function Model:outline(body)
  eachLeaf(body, function(s)
    if s:getKind() == 'rounded' then
      roundedLine(self, s, 1)
    elseif s:getKind() == 'circle' then
      local x, y = s:getCentroid()
      ring(self, x, y, s:getRadius(), 1)
    else
      for _, x1, y1, x2, y2 in s:ipairs() do segment(self, x1, y1, x2, y2, 1) end
    end
  end)
end

function Model:line(x1, y1, x2, y2, _, width)
  segment(self, x1, y1, x2, y2, (width or 1) / 2 + 0.5)
end

function Model:disc(x, y, r)
  disc(self, x, y, r + 0.5)
end

function Model:arrow(x1, y1, x2, y2, _, width)
  local r = (width or 1) / 2 + 0.5
  local ax, ay, bx, by = geom.arrowHead(x1, y1, x2, y2)
  segment(self, x1, y1, x2, y2, r)
  segment(self, ax, ay, x2, y2, r)
  segment(self, bx, by, x2, y2, r)
end

-- strike's debug helpers, as strike/draw.lua draws them (1-px lines).

function Model:mtv(mtv)
  if mtv.separating then return end
  local ax, ay = mtv.colliderShape:getCentroid()
  local bx, by = mtv.collidedShape:getCentroid()
  segment(self, ax, ay, bx, by, 1)
  segment(self, ax, ay, ax + mtv.x, ay + mtv.y, 1)
end

function Model:norms(body, len)
  len = len or 15
  eachLeaf(body, function(s)
    if s:getKind() == 'circle' then
      local x, y = s:getCentroid()
      local r = s:getRadius()
      for k = 0, 7 do
        local nx, ny = cos(k * pi / 4), sin(k * pi / 4)
        segment(self, x + nx * r, y + ny * r, x + nx * (r + len), y + ny * (r + len), 1)
      end
    else
      -- (a rounded shape's normals start on its boundary: its core's faces moved out)
      local r = s:getKind() == 'rounded' and s:getRounding() or 0
      for i, x1, y1, x2, y2 in s:ipairs() do
        local nx, ny = s:getNormal(i)
        local mx, my = (x1 + x2) / 2 + nx * r, (y1 + y2) / 2 + ny * r
        segment(self, mx, my, mx + nx * len, my + ny * len, 1)
      end
    end
  end)
end

function Model:proj(mtv)
  local nx, ny = mtv.nx, mtv.ny
  local ox, oy = mtv.colliderShape:getCentroid()
  local o = nx * ox + ny * oy
  for k, s in ipairs({ mtv.colliderShape, mtv.collidedShape }) do
    local lo, hi = s:project(nx, ny)
    local px, py = -ny * 4 * k, nx * 4 * k
    segment(self, ox + nx * (lo - o) + px, oy + ny * (lo - o) + py, ox + nx * (hi - o) + px, oy + ny * (hi - o) + py, 1)
  end
end

function Model:contacts(contacts, len)
  if not contacts then return end
  len = len or 15
  for i = 1, contacts.count do
    local p = contacts[i]
    disc(self, p.x, p.y, 3.5)
    local nx, ny = p.nx or contacts.nx, p.ny or contacts.ny -- (a compound's points: each its pair's)
    segment(self, p.x, p.y, p.x + nx * len, p.y + ny * len, 1)
  end
end

function Model:ray(body, x, y, dx, dy, maxDistance)
  local t, hx, hy, nx, ny = body:rayCast(x, y, dx, dy, maxDistance)
  if t then
    segment(self, x, y, hx, hy, 1)
    disc(self, hx, hy, 3.5)
    segment(self, hx, hy, hx + nx * 15, hy + ny * 15, 1)
  else
    local l = sqrt(dx * dx + dy * dy)
    local reach = maxDistance or 1e4
    segment(self, x, y, x + dx / l * reach, y + dy / l * reach, 1)
  end
  return t
end

local function nodeBox(self, x0, y0, x1, y1)
  segment(self, x0, y0, x1, y0, 1)
  segment(self, x1, y0, x1, y1, 1)
  segment(self, x1, y1, x0, y1, 1)
  segment(self, x0, y1, x0, y0, 1)
end

--- A space as S.howSpace draws it (strike/draw.lua): every body outlined (1 px), then every
--- box of its broadphase (1-px rectangles, visited as S.howSpace visits them).
function Model:space(space)
  local bodies, n = space:bodies()
  for i = 1, n do self:outline(bodies[i]) end
  space:_eachNode(nodeBox, self)
end

-- The marks and the fills (from index `from` on) that come within CAP of a box: the only
-- ones that can matter to a pixel in it.
local function near(self, x0, y0, x1, y1, from)
  local marks, fills = {}, {}
  for _, m in ipairs(self.marks) do
    if m.maxx > x0 - CAP and m.minx < x1 + CAP and m.maxy > y0 - CAP and m.miny < y1 + CAP then
      marks[#marks + 1] = m
    end
  end
  for i = from, #self.fills do
    local f = self.fills[i]
    if f.maxx > x0 - CAP and f.minx < x1 + CAP and f.maxy > y0 - CAP and f.miny < y1 + CAP then
      fills[#fills + 1] = f
    end
  end
  return marks, fills
end

-- Clearance of the pixel centre (px, py): how far it is from every mark, from the
-- boundary of fill `target` (inside it) and from every fill drawn after it (outside them).
-- `target` nil means plain background: outside every fill. Capped at CAP. `marks` and
-- `fills` narrow the search (see near); by default, everything that matters.
function Model:clearance(px, py, target, marks, fills)
  if not marks then
    marks, fills = near(self, px, py, px, py, target and target.order + 1 or 1)
  end
  local c = CAP
  for i = 1, #marks do
    local m = marks[i]
    if px > m.minx - c and px < m.maxx + c and py > m.miny - c and py < m.maxy + c then
      local d = markDistance(m, px, py)
      if d < c then c = d end
    end
  end
  if target then
    local d = fillDistance(target, px, py)
    if d < c then c = d end
  end
  for i = 1, #fills do
    local f = fills[i]
    if px > f.minx - c and px < f.maxx + c and py > f.miny - c and py < f.maxy + c then
      local d = -fillDistance(f, px, py)
      if d < c then c = d end
    end
  end
  -- the screen's own border
  return min(c, px, py, self.w - px, self.h - py)
end

-- The best pixel inside fill f: the highest clearance, then the nearest to the middle of
-- its bounding box (scan order breaks the remaining ties, so the choice is deterministic).
local function bestIn(self, f)
  local mx, my = (f.minx + f.maxx) / 2, (f.miny + f.maxy) / 2
  local marks, fills = near(self, f.minx, f.miny, f.maxx, f.maxy, f.order + 1)
  local bestC, bestD, bx, by = -huge, huge, nil, nil
  -- every pixel of small fills, every 2nd or 3rd of big ones
  local step = max(1, floor(max(f.maxx - f.minx, f.maxy - f.miny) / 80))
  for y = floor(f.miny), floor(f.maxy), step do
    for x = floor(f.minx), floor(f.maxx), step do
      local c = self:clearance(x + 0.5, y + 0.5, f, marks, fills)
      if c >= bestC then
        local d = (x + 0.5 - mx) ^ 2 + (y + 0.5 - my) ^ 2
        if c > bestC or d < bestD then bestC, bestD, bx, by = c, d, x, y end
      end
    end
  end
  return bx, by, bestC
end

--- A probe inside the body painted with `label` (its best leaf), or nil when no pixel of
--- it has probe.MARGIN clearance.
---@param label string
---@return table|nil probe
function Model:probeFill(label)
  local best
  for _, f in ipairs(self.fills) do
    if f.label == label then
      local x, y, c = bestIn(self, f)
      if x and c >= probe.MARGIN and (not best or c > best.c) then
        best = { x = x, y = y, r = f.rgb[1], g = f.rgb[2], b = f.rgb[3], what = label, c = c }
      end
    end
  end
  if best then best.c = nil end
  return best
end

--- Up to n background probes of colour rgb, spread over the screen: the candidates of a
--- 10-px grid that are fully clear (clearance CAP), chosen greedily each the farthest from
--- those already chosen, starting from the one nearest the screen's centre.
---@param n integer @param rgb number[]
---@return table[]
function Model:probeBackground(n, rgb)
  local cands = {}
  for y = 5, self.h - 5, 10 do
    local marks, fills = near(self, 0, y, self.w, y + 1, 1) -- one row at a time
    for x = 5, self.w - 5, 10 do
      if self:clearance(x + 0.5, y + 0.5, nil, marks, fills) >= CAP then cands[#cands + 1] = { x, y } end
    end
  end
  local chosen = {}
  local cx, cy = self.w / 2, self.h / 2
  local dist = {} -- each candidate's squared distance to the nearest chosen point
  for i, p in ipairs(cands) do dist[i] = -((p[1] - cx) ^ 2 + (p[2] - cy) ^ 2) end -- first: nearest the centre
  for k = 1, math.min(n, #cands) do
    local bi, bd = nil, -huge
    for i = 1, #cands do
      if dist[i] > bd then bi, bd = i, dist[i] end
    end
    local p = cands[bi]
    chosen[k] = { x = p[1], y = p[2], r = rgb[1], g = rgb[2], b = rgb[3], what = 'background ' .. k }
    for i, q in ipairs(cands) do
      local d = (q[1] - p[1]) ^ 2 + (q[2] - p[2]) ^ 2
      if k == 1 or d < dist[i] then dist[i] = d end
    end
  end
  return chosen
end

--- The probes of a scene's state: paint it into a model (with the overlays of `layout`
--- reserved), then one probe per label (for the labels that have room, at most
--- `maxShapes` of them, in order) and `nBackground` background probes.
---@param scene table the scene module (its paint function and help) @param state table
---@param labels string[] @param nBackground integer @param layout table demo/util/layout
---@param maxShapes integer|nil
---@return table[]
function probe.collect(scene, state, labels, nBackground, layout, maxShapes)
  local w, h = state.w or layout.WIDTH, state.h or layout.HEIGHT
  local model = probe.model(w, h)
  scene.paint(state, model)
  for _, r in ipairs(layout.reserved(scene, w, h)) do model:reserve(r[1], r[2], r[3], r[4]) end
  local list = {}
  for _, label in ipairs(labels) do
    if maxShapes and #list >= maxShapes then break end
    list[#list + 1] = model:probeFill(label)
  end
  for _, p in ipairs(model:probeBackground(nBackground, layout.BACKGROUND)) do list[#list + 1] = p end
  return list
end

return probe
