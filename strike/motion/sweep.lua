--- S.weep: when does a moving body first touch another? The pair loop over two bodies'
--- leaves around the kernels of motion/kernels.lua, and the conservative advancement that
--- turns a rotating move into distance queries.
---
--- A hit is `{t =, x =, y =, nx =, ny =, overlapping =}`: t in [0, 1] the fraction of the
--- move at the first touch, (x, y) a point where they touch then, (nx, ny) the unit normal
--- from b toward a. Bodies that already overlap (as S.triking says) give t = 0 and
--- overlapping = true, with the normal opposite S.triking's MTV and the point midway between
--- the points of each that reach deepest into the other. A pair that only touches at the
--- start and does not move into each other is no hit (the sweep finds the first moment they
--- would begin to overlap).
---
--- Translation alone is exact to round-off: the earliest hit over every pair of leaves.
--- Leaves that meet at the same t (within the kernels' TIE) are decided by the move: a face
--- beats a corner (kernels.lua, "Corners"), then the hit the move grazes most.
---
--- Rotation: conservative advancement (B. Mirtich, "Impulse-based Dynamic Simulation of
--- Rigid Body Systems", PhD thesis, UC Berkeley 1996, ch. 2; as Box2D's b2TimeOfImpact
--- bounds the motion): no point of a moves faster than |d| + |angle| * rho per unit of t,
--- rho its farthest reach from its centroid, so after measuring the distance d between the
--- bodies the clock can advance by d / (|d| + |angle| rho) without missing a touch. The
--- steps stop when the distance is within ROTATION_TOL (relative to the bodies' size) or
--- after MAX_STEPS; the t reported is never after the true first touch.
local ROOT = (...):match('^(.-)%.motion%.[^%.]+$')
local kernels = require(ROOT .. '.motion.kernels')
local layout = require(ROOT .. '.base.layout')
local compound = require(ROOT .. '.collide.compound')
local Collider = require(ROOT .. '.colliders.Collider')
local Shape = require(ROOT .. '.base.Shape')
local MTV = require(ROOT .. '.collide.MTV')
local args = require(ROOT .. '.collide.args')
local check = require(ROOT .. '.check')
local limits = require(ROOT .. '.limits')
local checkReach, ROUND = limits.checkReach, limits.ROUND

local COUNT, DIRTY, X, Y, R = layout.COUNT, layout.DIRTY, layout.X, layout.Y, layout.R
local STRIDE, VY, NX, NY, D = layout.STRIDE, layout.VY, layout.NX, layout.NY, layout.D
local CHAIN_SIZE, HASPREV = layout.CHAIN_SIZE, layout.HASPREV
local G1X, G1Y, G2X, G2Y = layout.G1X, layout.G1Y, layout.G2X, layout.G2Y
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local toi, span, coreDistance, reach = kernels.toi, kernels.span, kernels.coreDistance, kernels.reach
local TIE = kernels.TIE
local support, coreOverlap, APPROACH = kernels.support, kernels.coreOverlap, kernels.APPROACH
local collide, leafList, root = compound.collide, Collider._leafList, Shape._rootOf
local kinds = require(ROOT .. '.collide.dispatch').kind
local badKind = require(ROOT .. '.reserved').badKind
local finite, fail, describe = check.finite, check.fail, check.describe
local sqrt, abs, cos, sin, huge, type = math.sqrt, math.abs, math.cos, math.sin, math.huge, type

local sweep = {}

--- Distance within which a rotating sweep counts as touching, relative to the two bodies'
--- size (the sum of their radii).
sweep.ROTATION_TOL = 1e-9
--- The most advancement steps of a rotating sweep.
sweep.MAX_STEPS = 500

local mtv = MTV()
local one1, one2 = {}, {}

-- A body's leaves (refreshed): a collider's list, or a bare shape in `one`.
local function leavesOf(body, one, fname, owner)
  -- (one leaf, the common case, without a loop: a collider's `_single`, its only leaf while
  -- its list is current, else false; nil for a shape. LuaJIT traces one-trip loops badly.)
  -- (the kernels tell chain segments by their kind: a `_kind` a game changed is an error)
  local s = body._single
  if s == nil then s = body end
  if s then
    if s[DIRTY] then s:_refresh() end
    if not kinds[s._kind] then badKind(fname or 'strike', s, owner, body) end
    one[1] = s
    return one, 1
  end
  local list, n = leafList(body)
  for i = 1, n do
    s = list[i]
    if s[DIRTY] then s:_refresh() end
    if not kinds[s._kind] then badKind(fname or 'strike', s, owner, body) end
  end
  return list, n
end
--- leavesOf(body, one [, fname, owner]): a body's leaves, refreshed, and their count (a bare
--- shape in the one-slot list `one`); a leaf whose `_kind` the game changed is an error of
--- `fname` about `owner` (an argument's name).
---@param body strike.Collider|strike.Shape
---@param one table
---@param fname string|nil
---@param owner string|nil
---@return table list
---@return integer n
sweep.leavesOf = leavesOf

-- Fill `out` with a hit.
local function fill(out, t, x, y, nx, ny, overlapping)
  out.t, out.x, out.y, out.nx, out.ny, out.overlapping = t, x, y, nx, ny, overlapping
  return out
end

--- The overlap of bodies S.triking found colliding (its MTV in `m`), as a hit at t = 0.
---@param m strike.MTV
---@param out table
---@return table
function sweep.overlapHit(m, out)
  local nx, ny = m.nx, m.ny
  local a, b = m.colliderShape, m.collidedShape
  local ax, ay = support(a, nx, ny)
  local bx, by = support(b, -nx, -ny)
  return fill(out, 0, (ax + bx) / 2, (ay + by) / 2, -nx, -ny, true)
end

-- Is the hit (t, corner, |dn|) better than the best so far? Earlier; at the same time (tie
-- in t), a face over a corner, then the one the move grazes most.
local function better(t, corner, adn, bt, bcorner, badn, tieT)
  if t < bt - tieT then return true end
  if t > bt + tieT then return false end
  if corner ~= bcorner then return bcorner end
  return adn < badn
end
--- better(t, corner, adn, bt, bcorner, badn, tieT): whether a hit at t (a corner or not, with
--- |d . n| = adn) beats the best so far (see the header).
---@param t number
---@param corner boolean
---@param adn number
---@param bt number
---@param bcorner boolean
---@param badn number
---@param tieT number
---@return boolean
sweep.better = better

-- Best hit of a translation so far.
local ht, hx, hy, hnx, hny, hcorner, hadn = huge, 0, 0, 0, 0, false, huge

--- The earliest hit of body a's leaves moving by (dx, dy) against b's: false, or true with
--- the hit in sweep.t, .x, .y, .nx, .ny, .corner; sweep.overlap tells whether a pair of their
--- leaves overlapped at the start (then the bodies' S.triking has the answer).
---@param la table
---@param na integer
---@param lb table
---@param nb integer
---@param dx number
---@param dy number
---@return boolean
function sweep.translate(la, na, lb, nb, dx, dy)
  ht, hcorner, hadn = huge, false, huge
  local overlap = false
  local dl = sqrt(dx * dx + dy * dy)
  for i = 1, na do
    local A = la[i]
    local m, ea -- (A's part of the tolerance, when a pair needs it)
    for j = 1, nb do
      local B = lb[j]
      -- (bounds of the move against B's bounds first: most pairs end here)
      if A[MINX] + (dx < 0 and dx or 0) <= B[MAXX] and A[MAXX] + (dx > 0 and dx or 0) >= B[MINX]
        and A[MINY] + (dy < 0 and dy or 0) <= B[MAXY] and A[MAXY] + (dy > 0 and dy or 0) >= B[MINY] then
        if not m then -- (the touching tolerance, kernels.lua's Tolerances: A's part once)
          m = ROUND * reach(A, dx, dy)
          ea = (A[MAXX] - A[MINX]) + (A[MAXY] - A[MINY])
        end
        local eb = (B[MAXX] - B[MINX]) + (B[MAXY] - B[MINY])
        local tol = TIE * (ea < eb and ea or eb) + m
        local hit = toi(A, B, dx, dy, tol)
        if kernels.overlap then overlap = true end
        if hit then
          local t, nx, ny = kernels.t, kernels.nx, kernels.ny
          local adn = abs(dx * nx + dy * ny)
          if better(t, kernels.corner, adn, ht, hcorner, hadn, dl > 0 and tol / dl or 0) then
            ht, hx, hy, hnx, hny, hcorner, hadn = t, kernels.x, kernels.y, nx, ny, kernels.corner, adn
          end
        end
      end
    end
  end
  sweep.overlap = overlap
  if ht == huge then return false end
  sweep.t, sweep.x, sweep.y, sweep.nx, sweep.ny, sweep.corner = ht, hx, hy, hnx, hny, hcorner
  return true
end
sweep.t, sweep.x, sweep.y, sweep.nx, sweep.ny, sweep.corner = 0, 0, 0, 0, 0, false
-- sweep.overlap: whether the last translate met a pair of leaves overlapping at the start.
sweep.overlap = false

------------------------------------------------------------------ rotation

-- Copies of a's leaves at a time of the advancement, one per leaf (grown once).
local placed = {}

-- Put leaf `src` turned by (c, s) about (cx, cy) and moved by (tx, ty) into `dst`: the slots
-- the kernels read.
local function place(src, dst, cx, cy, c, s, tx, ty)
  dst[COUNT], dst[R], dst._kind = src[COUNT], src[R], src._kind
  local k0, k1 = span(src)
  local x0, y0, x1, y1 = huge, huge, -huge, -huge
  local px, py = src[X] - cx, src[Y] - cy
  dst[X], dst[Y] = cx + c * px - s * py + tx, cy + s * px + c * py + ty
  for k = k0, k1, STRIDE do
    px, py = src[k] - cx, src[k + VY] - cy
    local x, y = cx + c * px - s * py + tx, cy + s * px + c * py + ty
    dst[k], dst[k + VY] = x, y
    if src[COUNT] then
      local nx, ny = src[k + NX], src[k + NY]
      nx, ny = c * nx - s * ny, s * nx + c * ny
      dst[k + NX], dst[k + NY], dst[k + D] = nx, ny, nx * x + ny * y
    end
    if x < x0 then x0 = x end
    if y < y0 then y0 = y end
    if x > x1 then x1 = x end
    if y > y1 then y1 = y end
  end
  local r = src[R]
  dst[MINX], dst[MINY], dst[MAXX], dst[MAXY] = x0 - r, y0 - r, x1 + r, y1 + r
  if src._kind == 'chain' then
    for k = HASPREV, CHAIN_SIZE do dst[k] = src[k] end
    dst[G1X], dst[G1Y] = c * src[G1X] - s * src[G1Y], s * src[G1X] + c * src[G1Y]
    dst[G2X], dst[G2Y] = c * src[G2X] - s * src[G2Y], s * src[G2X] + c * src[G2Y]
  end
end

-- Is leaf A (at the start) in front of chain segment B, when B is one (and vice versa)?
local P1 = layout.base(1)
local function faces(A, B)
  if A._kind == 'chain' then
    if B._kind == 'chain' then return false end
    A, B = B, A
  end
  if B._kind ~= 'chain' then return true end
  return B[P1 + NX] * (A[X] - B[P1]) + B[P1 + NY] * (A[Y] - B[P1 + VY]) >= 0
end

-- The smallest gap between the placed copies of a's leaves and b's (pairs that `faces`
-- allowed at the start: mask[i * nb + j]): gap, the closest points on the two surfaces, and
-- the unit normal from b toward a (along the cores' closest points; 0, 0 when they meet).
local mask = {}
local function gap(na, lb, nb)
  local best, bax, bay, bbx, bby, bnx, bny = huge, 0, 0, 0, 0, 0, 0
  for i = 1, na do
    local A = placed[i]
    for j = 1, nb do
      if mask[(i - 1) * nb + j] then
        local B = lb[j]
        local d, ax, ay, bx, by = coreDistance(A, B)
        d = d - A[R] - B[R]
        if d < best then
          local nx, ny = ax - bx, ay - by
          local l = sqrt(nx * nx + ny * ny)
          if l > 0 then
            nx, ny = nx / l, ny / l
          else -- (the cores meet: the axis that separates them least)
            local _
            _, nx, ny = coreOverlap(A, B)
          end
          -- (the surface points, along the line of the core points)
          ax, ay, bx, by = ax - nx * A[R], ay - ny * A[R], bx + nx * B[R], by + ny * B[R]
          best, bax, bay, bbx, bby, bnx, bny = d, ax, ay, bx, by, nx, ny
        end
      end
    end
  end
  return best, bax, bay, bbx, bby, bnx, bny
end

-- The hit of a rotating sweep at t: the middle of the closest points, and the normal (when
-- there is none, against the move instead).
local function rotHit(out, t, ax, ay, bx, by, nx, ny, dx, dy)
  if nx == 0 and ny == 0 then
    local l = sqrt(dx * dx + dy * dy)
    if l > 0 then nx, ny = -dx / l, -dy / l else nx = 1 end
  end
  return fill(out, t, (ax + bx) / 2, (ay + by) / 2, nx, ny, false)
end

-- The rotating sweep (see the header): writes the hit into `out`, or returns false.
local function rotate(la, na, lb, nb, cx, cy, dx, dy, angle, out)
  local rho, size = 0, 0
  for i = 1, na do
    local A = la[i]
    local k0, k1 = span(A)
    for k = k0, k1, STRIDE do
      local l = sqrt((A[k] - cx) ^ 2 + (A[k + VY] - cy) ^ 2) + A[R]
      if l > rho then rho = l end
    end
    if not placed[i] then placed[i] = {} end
  end
  for j = 1, nb do
    local B = lb[j]
    local l = (B[MAXX] - B[MINX]) + (B[MAXY] - B[MINY])
    if l > size then size = l end
    for i = 1, na do mask[(i - 1) * nb + j] = faces(la[i], B) end
  end
  local target = sweep.ROTATION_TOL * (size + 2 * rho)
  local speed = sqrt(dx * dx + dy * dy) + abs(angle) * rho
  local t, last = 0, sweep.MAX_STEPS
  for step = 0, last do
    local c, s = cos(angle * t), sin(angle * t)
    for i = 1, na do place(la[i], placed[i], cx, cy, c, s, t * dx, t * dy) end
    local d, ax, ay, bx, by, nx, ny = gap(na, lb, nb)
    if d == huge then return false end -- (no pair may meet)
    -- (touching, or out of steps: then t is still before the first touch)
    if d <= target or step == last then
      if t == 0 then -- touching at the start: a hit only when a's touching point goes in
        local vx, vy = dx - angle * (ay - cy), dy + angle * (ax - cx)
        -- luacheck: ignore 581 (NaN reads as no hit)
        if not (vx * nx + vy * ny < -APPROACH * sqrt(vx * vx + vy * vy)) then return false end
      end
      return rotHit(out, t, ax, ay, bx, by, nx, ny, dx, dy)
    end
    t = t + d / speed
    if t > 1 then return false end
  end
end

------------------------------------------------------------------ S.weep

local FNAME = 'strike.weep'

--- Raise the error for argument `i` of `fname` at the caller's line unless `v` is a body (a
--- strike shape or collider).
---@param fname string
---@param v any
---@param i integer
function sweep.checkBody(fname, v, i)
  if type(v) ~= 'table' or not (v._type == 'shape' and args.isShape(v) or v._type == 'collider'
    and args.isCollider(v)) then
    args.badBody(fname, i, v)
  end
end
local checkBody = sweep.checkBody

--- Sweep body a by (dx, dy) (turning by `angle` about its centroid, linearly with t) against
--- body b, which stays: false when they never touch, else the hit (see the header), filled
--- into `out` when given.
---@param a strike.Collider|strike.Shape
---@param dx number
---@param dy number
---@param b strike.Collider|strike.Shape
---@param angle number|nil
---@param out table|nil
---@return table|false
function sweep.weep(a, dx, dy, b, angle, out)
  checkBody(FNAME, a, 1)
  if not (finite(dx) and finite(dy)) then
    check.number(dx, FNAME, 'argument 2 (dx)')
    check.number(dy, FNAME, 'argument 3 (dy)')
  end
  checkBody(FNAME, b, 4)
  if angle ~= nil and not finite(angle) then
    fail(('%s: argument 5 (angle) must be a finite number or nil, got %s'):format(FNAME, describe(angle)))
  end
  if out ~= nil and (type(out) ~= 'table' or getmetatable(out) ~= nil) then
    fail(('%s: argument 6 (out) must be a plain table for the hit (a previous hit, or {}), got %s')
      :format(FNAME, check.what(out)))
  end
  do -- (the range of motion: limits.lua)
    local x, y = a:getCentroid()
    checkReach(FNAME, a:getRadius(), x, y, x + dx, y + dy)
  end
  local ra = a._parent and root(a) or a
  local rb = b._parent and root(b) or b
  if ra == rb then return false end -- (members of one collider never meet)
  out = out or {}
  local la, na = leavesOf(a, one1, FNAME, 'argument 1') -- (first: they check the leaves' kinds)
  local lb, nb = leavesOf(b, one2, FNAME, 'argument 4')
  local m = collide(a, b, mtv)
  if m then return sweep.overlapHit(m, out) end
  if na == 0 or nb == 0 then return false end -- (an empty collider meets nothing)
  if angle == nil or angle == 0 then
    if not sweep.translate(la, na, lb, nb, dx, dy) then return false end
    return fill(out, sweep.t, sweep.x, sweep.y, sweep.nx, sweep.ny, false)
  end
  local cx, cy = a:getCentroid()
  return rotate(la, na, lb, nb, cx, cy, dx, dy, angle, out)
end

return sweep
