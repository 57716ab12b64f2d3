--- The seeded worlds of bench/space.lua (issue 11's "Speed" workload), as plain numbers, so
--- that every library builds the same bodies: strike in bench/space.lua, HC and bump through
--- bench/adapters/space_*.lua, Box2D in the LÖVE program bench/lovephysics/ (which loads this
--- file too). No library is loaded here; the caller puts the repository root on package.path.
---
--- A world of n bodies: body i is
---   i % 3 == 0  an axis-aligned box, w and h uniform in 8-24 px;
---   i % 3 == 1  a regular polygon of 4-8 sides (uniform integer), circumradius 5-14 px, turned
---               by a uniform angle;
---   i % 3 == 2  a circle of radius 4-12 px;
--- centred uniformly in a square of side 40 sqrt(n), moving 0.5-2 px a frame in a uniform
--- direction and bouncing off the square's border.
local PRNG = require('spec.helpers.prng')

local sqrt, cos, sin, pi = math.sqrt, math.cos, math.sin, math.pi

local M = {}

M.BOX, M.POLYGON, M.CIRCLE = 0, 1, 2

--- A world: flat arrays indexed by body number.
---   kind[i]       M.BOX, M.POLYGON or M.CIRCLE
---   x[i], y[i]    centre (a polygon's centre is its centroid)
---   w[i], h[i]    a box's size
---   sides[i], r[i], angle[i]  a polygon's side count, circumradius and angle; r[i] a circle's radius
---   hw[i], hh[i]  half-sizes of the body's bounding box (exact for boxes and circles; for a polygon
---                 the exact bounds of its vertices about the centre, so bump's box is tight)
---   vx[i], vy[i]  velocity, px per frame
---@param n integer
---@param seed integer
---@return table
function M.world(n, seed)
  local rng = PRNG.new(seed)
  local side = 40 * sqrt(n)
  local w = { n = n, side = side, kind = {}, x = {}, y = {}, w = {}, h = {}, sides = {}, r = {}, angle = {},
    hw = {}, hh = {}, vx = {}, vy = {} }
  for i = 1, n do
    local k = i % 3
    w.kind[i] = k
    if k == M.BOX then
      w.w[i], w.h[i] = rng:range(8, 24), rng:range(8, 24)
      w.hw[i], w.hh[i] = w.w[i] / 2, w.h[i] / 2
    elseif k == M.POLYGON then
      w.sides[i], w.r[i], w.angle[i] = rng:int(4, 8), rng:range(5, 14), rng:range(0, 2 * pi)
      local v = M.vertices(w, i, 0, 0)
      local hw, hh = 0, 0
      for j = 1, #v, 2 do hw, hh = math.max(hw, math.abs(v[j])), math.max(hh, math.abs(v[j + 1])) end
      w.hw[i], w.hh[i] = hw, hh
    else
      w.r[i] = rng:range(4, 12)
      w.hw[i], w.hh[i] = w.r[i], w.r[i]
    end
    w.x[i], w.y[i] = rng:range(0, side), rng:range(0, side)
    local speed, a = rng:range(0.5, 2), rng:range(-pi, pi)
    w.vx[i], w.vy[i] = speed * cos(a), speed * sin(a)
  end
  return w
end

--- Polygon i's vertices as a flat list, centred on (cx, cy): the vertices strike's
--- S.hapes.RegularPolygon(cx, cy, n, r, angle) computes (vertex k at angle -2 pi k / n from
--- +y, unrotated), then turned by the body's angle about the centre. Peers build their
--- polygons from these.
---@param w table
---@param i integer
---@param cx number
---@param cy number
---@return number[]
function M.vertices(w, i, cx, cy)
  local n, r, a = w.sides[i], w.r[i], w.angle[i]
  local c, s = cos(a), sin(a)
  local v = {}
  for k = 1, n do
    local t = -2 * pi * k / n
    local px, py = r * sin(t), r * cos(t)
    v[2 * k - 1], v[2 * k] = cx + c * px - s * py, cy + s * px + c * py
  end
  return v
end

--- One frame of motion: every body moves by its velocity, bouncing off the border (a body
--- that would leave the square moves back by the same step instead, its velocity reversed).
---@param w table
function M.step(w)
  local x, y, vx, vy, side = w.x, w.y, w.vx, w.vy, w.side
  for i = 1, w.n do
    local dx, dy = vx[i], vy[i]
    local nx, ny = x[i] + dx, y[i] + dy
    if nx < 0 or nx > side then vx[i] = -dx; nx = x[i] - dx end
    if ny < 0 or ny > side then vy[i] = -dy; ny = y[i] - dy end
    x[i], y[i] = nx, ny
  end
end

--- Rays for the ray workload: origins uniform in the square of side `side`, unit directions
--- at uniform angles. Flat arrays ox, oy, dx, dy.
---@param count integer
---@param side number
---@param seed integer
---@return table
function M.rays(count, side, seed)
  local rng = PRNG.new(seed)
  local r = { count = count, ox = {}, oy = {}, dx = {}, dy = {} }
  for i = 1, count do
    r.ox[i], r.oy[i] = rng:range(0, side), rng:range(0, side)
    local a = rng:range(-pi, pi)
    r.dx[i], r.dy[i] = cos(a), sin(a)
  end
  return r
end

--- Bullets for the churn workload: circles of radius 2 at uniform points of the square.
---@param count integer
---@param side number
---@param seed integer
---@return table flat arrays x, y
function M.bullets(count, side, seed)
  local rng = PRNG.new(seed)
  local b = { count = count, x = {}, y = {} }
  for i = 1, count do b.x[i], b.y[i] = rng:range(0, side), rng:range(0, side) end
  return b
end

--- Median and minimum of a list of numbers (the list is sorted in place).
---@param t number[]
---@return number, number
function M.medianMin(t)
  table.sort(t)
  local n = #t
  if n == 0 then return 0 / 0, 0 / 0 end
  local med = n % 2 == 1 and t[(n + 1) / 2] or (t[n / 2] + t[n / 2 + 1]) / 2
  return med, t[1]
end

--- The seed of the world of n bodies (the same in every program).
---@param n integer
---@return integer
function M.seed(n)
  return 20261111 + n
end

--- Frames to time at n bodies when `frames` are asked for: all of them up to 5,000 bodies,
--- then fewer (at least 5) so that a run stays short: frames * 5000 / n.
---@param frames integer
---@param n integer
---@return integer timed, integer warm-up
function M.frames(frames, n)
  local timed = math.max(5, math.min(frames, math.floor(frames * 5000 / n)))
  return timed, math.max(3, math.min(10, math.floor(timed / 3)))
end

return M
