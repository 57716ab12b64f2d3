--- Tiled objects as strike shapes, for strike.tiled: where Tiled draws each kind of object,
--- and how a tile's image (and the collision shapes drawn on it) is placed, flipped and
--- scaled. Every placement is an affine map (x, y) -> (a x + b y + e, c x + d y + f), kept
--- as {a, b, c, d, e, f}: an object's own frame, a layer's offset, a tile's placement
--- compose into one, and the shapes are built from the points it gives.
---
--- Tiled's conventions (docs/reference/tmx-map-format.rst and global-tile-ids.rst in
--- github.com/mapeditor/tiled; its renderer, src/libtiled/maprenderer.cpp, CellRenderer::
--- render, and orthogonalrenderer.cpp, for how tiles are drawn), read for the facts only:
---   * y grows downward; an object's `rotation` is in degrees, clockwise, about its (x, y);
---   * a rectangle, an ellipse, a capsule or a text box spans (x, y) to (x + width, y +
---     height) before the rotation: (x, y) is its top-left corner; a capsule is the rounded
---     rectangle whose corner radius is half its shorter side; a polygon's or polyline's
---     points are relative to (x, y); a point is (x, y);
---   * a tile object (one with a gid) shows its tile scaled to (width, height), placed by its
---     tileset's `objectalignment` ((x, y) is the bottom-left corner when unspecified, on
---     orthogonal maps) and rotated about (x, y);
---   * a tile is drawn scaled from its image size to its box (its own size on a tile layer,
---     the map's grid with tilerendersize 'grid', an object's size for a tile object; with
---     fillmode 'preserve-aspect-fit', by the smaller of the two scales, centred), moved by
---     its tileset's tileoffset times that scale, and flipped about its centre: anti-
---     diagonally first (x and y swapped: drawn turned 90 degrees clockwise with its
---     horizontal flip taken from the vertical flag and its vertical flip from the opposite
---     of the horizontal one, its box kept at the same bottom-left corner), then
---     horizontally and vertically. A tile on a tile layer sits on its cell's bottom-left
---     corner, growing up and right when larger than the grid.
local ROOT = (...):match('^(.-)%.tiled%.[^%.]+$')
local map = require(ROOT .. '.tiled.map')
local Rectangle = require(ROOT .. '.shapes.Rectangle')
local Circle = require(ROOT .. '.shapes.Circle')
local Ellipse = require(ROOT .. '.shapes.Ellipse')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local Capsule = require(ROOT .. '.shapes.Capsule')
local Point = require(ROOT .. '.shapes.Point')
local Collider = require(ROOT .. '.colliders.Collider')
local Concave = require(ROOT .. '.colliders.Concave')
local Chain = require(ROOT .. '.colliders.Chain')
local atan2 = require(ROOT .. '.compat').atan2

local fail, number, describe = map.fail, map.number, require(ROOT .. '.check').describe
local abs, sqrt, cos, sin, pi, rad, type = math.abs, math.sqrt, math.cos, math.sin, math.pi, math.rad, type

local M = {}

--- The number of segments of an ellipse's polygon: 32 inscribed segments, whose area is
--- 32 sin(2 pi / 32) / (2 pi) = 0.9936 of the ellipse's (an affine image of a regular polygon
--- keeps that ratio), with the four extreme points on the ellipse: its bounding box is
--- the object's (to rounding).
M.ELLIPSE_SEGMENTS = 32
local N = M.ELLIPSE_SEGMENTS
-- and a capsule's polygon (only when a tile's non-uniform scale stretches one): per cap
local CAP_SEGMENTS = 16

-- Affine maps ------------------------------------------------------------------------------

--- The map that moves by (e, f).
---@param e number
---@param f number
---@return number[]
function M.translation(e, f) return { 1, 0, 0, 1, e, f } end

--- P after Q: the map x -> P(Q(x)).
---@param P number[]
---@param Q number[]
---@return number[]
function M.compose(P, Q)
  local a, b, c, d = P[1], P[2], P[3], P[4]
  return { a * Q[1] + b * Q[3], a * Q[2] + b * Q[4], c * Q[1] + d * Q[3], c * Q[2] + d * Q[4],
    a * Q[5] + b * Q[6] + P[5], c * Q[5] + d * Q[6] + P[6] }
end

--- Where the map P takes (x, y).
---@param P number[]
---@param x number
---@param y number
---@return number
---@return number
function M.apply(P, x, y) return P[1] * x + P[2] * y + P[5], P[3] * x + P[4] * y + P[6] end
local apply = M.apply

-- The cosine and sine of a turn by `deg` degrees, exact at multiples of 90.
local QUARTER = { [0] = { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } }
local function turn(deg)
  if deg % 90 == 0 then
    local q = QUARTER[(deg / 90) % 4]
    return q[1], q[2]
  end
  local r = rad(deg)
  return cos(r), sin(r)
end

--- An object's frame: its own coordinates (its (x, y) at the origin, unrotated) to its
--- layer's, turned by its rotation (degrees, clockwise on a y-down screen) about (x, y).
---@param obj table
---@param where string|table a place (map.text)
---@return number[]
function M.frame(obj, where)
  local x = number(obj.x, where, 'x', 0)
  local y = number(obj.y, where, 'y', 0)
  local c, s = turn(number(obj.rotation, where, 'rotation', 0))
  return { c, -s, s, c, x, y }
end

-- Is P's linear part a rotation times a scale (a mirror allowed)? Then its scale too.
local function similarity(P)
  local a, b, c, d = P[1], P[2], P[3], P[4]
  local u, v = a * a + c * c, b * b + d * d
  local tol = 1e-12 * (u + v)
  if abs(u - v) <= tol and abs(a * b + c * d) <= tol then return true, sqrt(u) end
  return false, 0
end

-- The angle of the direction (x, y) as a rectangle's or ellipse's turn: in (-pi/2, pi/2],
-- since a half turn leaves them as they are.
local function halfTurn(x, y)
  local t = atan2(y, x)
  if t > pi / 2 then t = t - pi elseif t <= -pi / 2 then t = t + pi end
  return t
end

local function det(P) return P[1] * P[4] - P[2] * P[3] end

-- Shapes -------------------------------------------------------------------------------------

local function flat(P, xs, ys, n, reverse)
  local pts = {}
  for i = 1, n do
    local k = reverse and n + 1 - i or i
    pts[2 * i - 1], pts[2 * i] = apply(P, xs[k], ys[k])
  end
  return pts
end

-- The box (x0, y0, w, h) of local coordinates under P: a rectangle (a parallelogram under a
-- map that is neither a similarity nor axis-aligned).
local function box(P, x0, y0, w, h)
  local a, b, c, d = P[1], P[2], P[3], P[4]
  local cx, cy = apply(P, x0 + w / 2, y0 + h / 2)
  if b == 0 and c == 0 then return Rectangle(cx, cy, w * abs(a), h * abs(d)) end
  if a == 0 and d == 0 then return Rectangle(cx, cy, h * abs(b), w * abs(c)) end
  local sim, s = similarity(P)
  if sim then return Rectangle(cx, cy, w * s, h * s, halfTurn(a, c)) end
  return ConvexPolygon(flat(P, { x0, x0 + w, x0 + w, x0 }, { y0, y0, y0 + h, y0 + h }, 4))
end

-- The ellipse in the box (x0, y0, w, h) under P: a circle when it stays round, else the
-- 32-gon of S.hapes.Ellipse (the affine image of its points when P stretches it askew).
local function ellipse(P, x0, y0, w, h)
  local a, b, c, d = P[1], P[2], P[3], P[4]
  local rx, ry = w / 2, h / 2
  local cx, cy = apply(P, x0 + rx, y0 + ry)
  local ex, ey, angle
  if b == 0 and c == 0 then
    ex, ey, angle = rx * abs(a), ry * abs(d), 0
  elseif a == 0 and d == 0 then
    ex, ey, angle = ry * abs(b), rx * abs(c), 0
  else
    local sim, s = similarity(P)
    if sim then
      ex, ey, angle = rx * s, ry * s, halfTurn(a, c)
    else
      local xs, ys = {}, {}
      for k = 1, N do
        local t = 2 * pi * (k - 1) / N
        xs[k], ys[k] = x0 + rx + rx * cos(t), y0 + ry + ry * sin(t)
      end
      return ConvexPolygon(flat(P, xs, ys, N))
    end
  end
  if ex == ey then return Circle(cx, cy, ex) end
  return Ellipse(cx, cy, ex, ey, N, angle)
end

-- The capsule in the box (x0, y0, w, h) (a rounded rectangle of corner radius half its
-- shorter side) under P.
local function capsule(P, x0, y0, w, h)
  if w == h then return ellipse(P, x0, y0, w, h) end
  local sim, s = similarity(P)
  local cx, cy = apply(P, x0 + w / 2, y0 + h / 2)
  local short, long, lx, ly = w, h, P[2], P[4] -- (the long side's direction: P of (0, 1) ...
  if w > h then short, long, lx, ly = h, w, P[1], P[3] end -- ... or of (1, 0))
  if sim then
    -- S.hapes.Capsule stands on its y axis; turned by t, that axis is (-sin t, cos t)
    local t = 0
    if ly == 0 then t = pi / 2 elseif lx ~= 0 then t = halfTurn(ly, -lx) end
    return Capsule(cx, cy, short * s, long * s, t)
  end
  -- stretched unevenly: the outline's points (two arcs of CAP_SEGMENTS) under P
  local r = short / 2
  local xs, ys, n = {}, {}, 0
  for cap = 0, 1 do
    for k = 0, CAP_SEGMENTS do
      local t = pi * (cap + k / CAP_SEGMENTS)
      local ux, uy = cos(t), sin(t) -- (the first cap's arc turns from +x through +y)
      n = n + 1
      if w > h then
        local ccx = cap == 0 and x0 + w - r or x0 + r
        xs[n], ys[n] = ccx + r * uy, y0 + r - r * ux
      else
        local ccy = cap == 0 and y0 + h - r or y0 + r
        xs[n], ys[n] = x0 + r + r * ux, ccy + r * uy
      end
    end
  end
  return ConvexPolygon(flat(P, xs, ys, n))
end

-- Are the points, in order, the corners of a convex polygon (every turn the same way, and
-- once around)? Collinear points and repeats are allowed (ConvexPolygon drops them).
local function convex(xs, ys, n)
  local sign, total = 0, 0
  for i = 1, n do
    local j = i % n + 1
    local k = j % n + 1
    local ex, ey = xs[j] - xs[i], ys[j] - ys[i]
    local fx, fy = xs[k] - xs[j], ys[k] - ys[j]
    local cr = ex * fy - ey * fx
    if cr > 0 then
      if sign < 0 then return false end
      sign = 1
    elseif cr < 0 then
      if sign > 0 then return false end
      sign = -1
    end
    total = total + atan2(cr, ex * fx + ey * fy)
  end
  return sign ~= 0 and abs(abs(total) - 2 * pi) < 1e-6
end

-- The points of a polygon or polyline object: xs, ys, n (relative to the object's (x, y)).
local function points(list, where, field)
  if type(list) ~= 'table' then fail(where, ('%s must be a list of points {x =, y =}, got %s')
    :format(field, describe(list)))
  end
  local xs, ys = {}, {}
  for i = 1, #list do
    local p = list[i]
    if type(p) ~= 'table' then
      fail(where, ('%s[%d] must be a point {x =, y =}, got %s'):format(field, i, describe(p)))
    end
    local x, y = p.x, p.y
    -- (the field's name written only for an error)
    if type(x) ~= 'number' or x - x ~= 0 then number(x, where, ('%s[%d].x'):format(field, i)) end
    if type(y) ~= 'number' or y - y ~= 0 then number(y, where, ('%s[%d].y'):format(field, i)) end
    xs[i], ys[i] = x, y
  end
  return xs, ys, #list
end

local SHAPES = { rectangle = true, ellipse = true, polygon = true, polyline = true, point = true, text = true,
  capsule = true }

--- What an object is: 'tile' (it has a gid), or its shape, from `shape` (the Lua export) or
--- from the fields a JSON map marks it with (ellipse, point, capsule: true; polygon,
--- polyline: its points; text: its text); 'rectangle' when none.
---@param obj table
---@param where string|table a place (map.text)
---@return string
function M.kind(obj, where)
  if obj.gid ~= nil then return 'tile' end
  local shape = obj.shape
  if shape ~= nil then
    if not SHAPES[shape] then
      fail(where, ('shape must be one of Tiled\'s (rectangle, ellipse, polygon, polyline, point, text, capsule), got'
        .. ' %s'):format(describe(shape)))
    end
    return shape
  end
  if obj.polygon ~= nil then return 'polygon' end
  if obj.polyline ~= nil then return 'polyline' end
  if obj.ellipse == true then return 'ellipse' end
  if obj.point == true then return 'point' end
  if obj.capsule == true then return 'capsule' end
  if obj.text ~= nil then return 'text' end
  return 'rectangle'
end

local function extent(obj, where, field)
  local v = obj[field]
  if type(v) ~= 'number' or v - v ~= 0 or v <= 0 then
    fail(where, ('%s must be a finite number > 0 for a %s, got %s'):format(field, M.kind(obj, where),
      describe(v)))
  end
  return v
end

--- Append the strike shapes (or colliders) of an object that is not a tile to `out`: `P`
--- takes the object's own coordinates (M.frame) to the world. `oneway` makes a polyline one
--- chain, solid on its left as drawn (see strike.tiled); otherwise it blocks both sides.
---@param out table
---@param obj table
---@param kind string M.kind's answer
---@param P number[]
---@param oneway boolean
---@param where string|table a place (map.text)
function M.add(out, obj, kind, P, oneway, where)
  local part
  if kind == 'rectangle' or kind == 'text' then
    part = box(P, 0, 0, extent(obj, where, 'width'), extent(obj, where, 'height'))
  elseif kind == 'ellipse' then
    part = ellipse(P, 0, 0, extent(obj, where, 'width'), extent(obj, where, 'height'))
  elseif kind == 'capsule' then
    part = capsule(P, 0, 0, extent(obj, where, 'width'), extent(obj, where, 'height'))
  elseif kind == 'point' then
    part = Point(apply(P, 0, 0))
  elseif kind == 'polygon' then
    local xs, ys, n = points(obj.polygon, where, 'polygon')
    local pts = flat(P, xs, ys, n)
    if n >= 3 and convex(xs, ys, n) then part = ConvexPolygon(pts) else part = Concave(pts) end
  else -- polyline
    local xs, ys, n = points(obj.polyline, where, 'polyline')
    -- (a mirror turns the drawing's left into its right: the points go the other way, so
    -- that the solid side stays where it was drawn)
    local mirrored = det(P) < 0
    if oneway then
      part = Chain(flat(P, xs, ys, n, mirrored))
    else
      part = Collider._of({ Chain(flat(P, xs, ys, n, false)), Chain(flat(P, xs, ys, n, true)) })
    end
  end
  out[#out + 1] = part
end

--- Append a tile's box (the whole image, where it is drawn) under P, the tile's placement.
---@param out table
---@param P number[]
---@param tw number the tile's image width
---@param th number and height
function M.addBox(out, P, tw, th)
  out[#out + 1] = box(P, 0, 0, tw, th)
end

--- The placement of a tile: the map from its image's coordinates ((0, 0) its top-left, (tw,
--- th) its bottom-right) to where Tiled draws it in a box of size w by h whose top-left is
--- (x, y), flipped by the gid's flags h, v, d, with the tileset's offset (ox, oy) and fill
--- mode (fit: preserve-aspect-fit).
---@param x number
---@param y number
---@param w number
---@param h number
---@param tw number
---@param th number
---@param ox number
---@param oy number
---@param fit boolean
---@param fh boolean
---@param fv boolean
---@param fd boolean
---@return number[]
function M.placement(x, y, w, h, tw, th, ox, oy, fit, fh, fv, fd)
  local sx, sy = w / tw, h / th
  if fit then
    local s = sx < sy and sx or sy
    sx, sy = s, s
  end
  local cx, cy = x + w / 2 + ox * sx, y + h / 2 + oy * sy
  if not fd then
    local a, d = fh and -sx or sx, fv and -sy or sy
    return { a, 0, 0, d, cx - a * tw / 2, cy - d * th / 2 }
  end
  -- turned a quarter clockwise, (x, y) -> (-y, x), after the flips that make it a swap
  local half = h / 2 - w / 2
  cx, cy = cx + half, cy + half
  local a = fv and -sx or sx           -- (its horizontal flip: the vertical flag)
  local d = fh and sy or -sy           -- (its vertical flip: not the horizontal flag)
  return { 0, -d, a, 0, cx + d * th / 2, cy - a * tw / 2 }
end

--- Whether the map P mirrors (its determinant is negative).
---@param P number[]
---@return boolean
function M.mirrors(P) return det(P) < 0 end

--- The bounds of the box (0, 0, w, h) under P when P keeps it axis-aligned, else nil:
--- `x0, y0, x1, y1`.
---@param P number[]
---@param w number
---@param h number
---@return number|nil
---@return number|nil
---@return number|nil
---@return number|nil
function M.axisBox(P, w, h)
  if not ((P[2] == 0 and P[3] == 0) or (P[1] == 0 and P[4] == 0)) then return nil end
  local x1, y1 = apply(P, 0, 0)
  local x2, y2 = apply(P, w, h)
  if x1 > x2 then x1, x2 = x2, x1 end
  if y1 > y2 then y1, y2 = y2, y1 end
  return x1, y1, x2, y2
end

return M
