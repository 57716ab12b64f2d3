--- The solid full-square tiles of a tile layer merged into as few bodies as possible, for
--- strike.tiled: one body per connected region (tiles that share a side and the same
--- options; tiles that meet only at a corner are two regions), holes and all.
---
--- A region is a Collider of axis-aligned rectangles whose shared faces are marked as seams
--- (`_seams`, strike/base/VertexShape.lua): the same mechanism that makes the pieces of an
--- S.trikers.Concave one solid. Why that and not the alternatives (each failure below is shown
--- in spec/tiled_tiles_spec.lua, "the alternatives"; docs/tiled.md gives
--- the cost of large regions):
---   * chains around the outlines (S.trikers.Chain loops, holes reversed) are ghost-free but
---     are surfaces, not solids: a body whose centre is inside passes through, containsPoint
---     is false inside, and nothing is pushed out;
---   * one S.trikers.Concave per region needs a simple outline: a region with a hole is not
---     one (a keyhole cut touches itself, which the decomposition refuses), and tiles meeting
---     at one corner neither;
---   * plain touching rectangles are solid and ghost-free for S.triking and space:move (the
---     outline rule, and move's skin), but their shared faces are surfaces to the collider
---     queries: a point on one is inside neither rectangle (queryPoint misses it) and a ray
---     from inside the region stops there. With the faces marked as seams, containsPoint is
---     true on them, rays report only the region's outline, and S.triking never ends a push on
---     a seam, as for a Concave.
---
--- The rectangles: each row's solid cells in maximal runs (cells of the same key side by side),
--- a run below another with exactly the same columns and key extending its rectangle
--- downward. So rectangles meet only along horizontal faces (two runs of a row never touch:
--- they would be one), a seam part of a face always ends at a corner of the region's outline,
--- and two seam parts of one face never touch. Regions are the connected components of the
--- rectangles (union-find over runs of consecutive rows that share a column and a key).
--- Everything is kept in flat arrays, indexed densely (by rectangle, by seam part, by region):
--- no table per tile, per run or per region, and one per rectangle with a seam that is not a
--- whole face.
local ROOT = (...):match('^(.-)%.tiled%.[^%.]+$')
local Rectangle = require(ROOT .. '.shapes.Rectangle')
local Collider = require(ROOT .. '.colliders.Collider')

local M = {}

-- LuaJIT runs this file in its interpreter (jit.off, for this chunk and every function in
-- it), as strike/geometry/decompose.lua: a level's tiles pass through here once, and on
-- random tiles its loops take a different path at nearly every branch. Compiled, it made
-- two thirds of the traces of S.tiled's bench map (196 of 300 for the tiles), and with them
-- the first load overflowed the standalone interpreter's 512 KB of machine code and flushed
-- every trace. Interpreted, in 8 fresh processes each (ms, min-median-max): the tiles
-- 39.7-41.3-43.8 -> 36.7-37.4-44.5, the whole map 76.5-83.4-124.0 -> 75.1-77.2-102.3 under
-- LÖVE's limits and 80.6-89.2-117.1 -> 75.3-75.8-88.2 under the standalone ones (609 -> 412
-- traces, no flush). The rectangles it builds are compiled as usual.
local jit = rawget(_G, 'jit')
if jit then jit.off(true, true) end

local Builder = {}
Builder.__index = Builder

--- A new, empty region builder. Feed it the runs of each row (rows in increasing order, each
--- row's runs in increasing column order) with runs, then finish; then read its regions.
---@return table
function M.new()
  return setmetatable({
    -- the rectangles: columns x0 to x1 and rows y0 to y1 (ends exclusive), key, union-find
    -- parent, and their seam parts above (tfirst, tcount) and below (bfirst, bcount): ranges
    -- of the parts' list
    n = 0, x0 = {}, y0 = {}, x1 = {}, y1 = {}, key = {}, parent = {},
    tfirst = {}, tcount = {}, bfirst = {}, bcount = {},
    -- the seam parts: each a new rectangle (pnew), the one above it (pabove) and the columns
    -- they share, pa to pb (exclusive). A rectangle's parts above it are made one after the
    -- other, and so are its parts below it (the rectangles under it come in column order, and
    -- each one's parts in column order too: one that reached past its right end would leave
    -- no room for another under it)
    np = 0, pnew = {}, pabove = {}, pa = {}, pb = {},
    -- the regions (finish): their count, and the rectangles of region k, in increasing order,
    -- are members[start[k] .. start[k + 1] - 1]
    nreg = 0, start = {}, members = {},
    -- the previous row's runs (column from, column to (exclusive), key, rectangle) and the
    -- current row's
    pc0 = {}, pc1 = {}, pkey = {}, prect = {}, pn = 0, prow = false,
    cc0 = {}, cc1 = {}, ckey = {}, crect = {}, cn = 0, crow = false,
  }, Builder)
end

local function find(parent, i)
  while parent[i] ~= i do
    local p = parent[parent[i]]
    parent[i] = p
    i = p
  end
  return i
end

local function union(parent, i, j)
  i, j = find(parent, i), find(parent, j)
  if i < j then parent[j] = i elseif j < i then parent[i] = j end
end

-- Link the current row's runs to the previous row's: extend, or start rectangles, with
-- their seams and unions; then the current row becomes the previous one.
local function endRow(self)
  local cn = self.cn
  if self.crow then
    local row = self.crow
    local adjacent = self.prow and row == self.prow + 1
    local pc0, pc1, pkey, prect, pn = self.pc0, self.pc1, self.pkey, self.prect, self.pn
    local cc0, cc1, ckey, crect = self.cc0, self.cc1, self.ckey, self.crect
    local x0, y0, x1, y1, key, parent = self.x0, self.y0, self.x1, self.y1, self.key, self.parent
    local tfirst, tcount, bfirst, bcount = self.tfirst, self.tcount, self.bfirst, self.bcount
    local pnew, pabove, pa, pb, np = self.pnew, self.pabove, self.pa, self.pb, self.np
    local j = 1
    for i = 1, cn do
      local c0, c1, k = cc0[i], cc1[i], ckey[i]
      local rect = false
      if adjacent then
        while j <= pn and pc1[j] <= c0 do j = j + 1 end
        if j <= pn and pc0[j] == c0 and pc1[j] == c1 and pkey[j] == k then
          rect = prect[j] -- the same columns and key: one rectangle, one row taller
          y1[rect] = row + 1
        end
      end
      if not rect then
        local n = self.n + 1
        self.n, rect = n, n
        x0[n], y0[n], x1[n], y1[n], key[n], parent[n] = c0, row, c1, row + 1, k, n
        tfirst[n], tcount[n], bfirst[n], bcount[n] = np + 1, 0, 0, 0
        if adjacent then
          -- every run above that shares a column with this one and has its key: a seam
          -- between the two rectangles, which are one region
          local jj = j
          while jj <= pn and pc0[jj] < c1 do
            if pkey[jj] == k then
              local a, b = pc0[jj], pc1[jj]
              if a < c0 then a = c0 end
              if b > c1 then b = c1 end
              local above = prect[jj]
              np = np + 1
              pnew[np], pabove[np], pa[np], pb[np] = n, above, a, b
              tcount[n] = tcount[n] + 1
              if bcount[above] == 0 then bfirst[above] = np end
              bcount[above] = bcount[above] + 1
              union(parent, n, above)
            end
            jj = jj + 1
          end
        end
      end
      crect[i] = rect
    end
    self.np = np
  end
  -- the current row becomes the previous one (the arrays swap: nothing allocated)
  self.pc0, self.cc0 = self.cc0, self.pc0
  self.pc1, self.cc1 = self.cc1, self.pc1
  self.pkey, self.ckey = self.ckey, self.pkey
  self.prect, self.crect = self.crect, self.prect
  self.pn, self.prow, self.cn = cn, self.crow, 0
end

--- Runs of solid cells of row r (rows in increasing order; a row skipped is a row without
--- solid tiles): run i is columns c0s[i] to c1s[i] - 1, of the key keys[i] > 0, for i = 1 to
--- n, in increasing column order. The current row again goes on with them (its next chunk),
--- and a run that starts where the last one ended, with its key, continues it (runs from two
--- chunks).
---@param r integer
---@param c0s integer[]
---@param c1s integer[]
---@param keys integer[]
---@param n integer
function Builder:runs(r, c0s, c1s, keys, n)
  if r ~= self.crow then
    endRow(self)
    self.crow = r
  end
  local cc0, cc1, ckey, cn = self.cc0, self.cc1, self.ckey, self.cn
  for i = 1, n do
    local c0, c1, key = c0s[i], c1s[i], keys[i]
    if cn > 0 and cc1[cn] == c0 and ckey[cn] == key then
      cc1[cn] = c1
    else
      cn = cn + 1
      cc0[cn], cc1[cn], ckey[cn] = c0, c1, key
    end
  end
  self.cn = cn
end

--- End the last row, and number the regions: 1 to the count returned, in the order of their
--- first rectangle (its first tile in row-major order); Builder:first and Builder:body read
--- region k.
---@return integer
function Builder:finish()
  endRow(self)
  self.prow = false
  local parent, n = self.parent, self.n
  -- a region's root is its lowest rectangle (union keeps the lower root), so the rectangles
  -- in increasing order meet each root before the rest of its region
  local regionOf, count, nreg = {}, {}, 0
  for i = 1, n do
    local r = find(parent, i)
    local k
    if r == i then
      nreg = nreg + 1
      k, count[nreg] = nreg, 0
    else
      k = regionOf[r]
    end
    regionOf[i], count[k] = k, count[k] + 1
  end
  -- the rectangles by region, each region's in increasing order (a counting sort)
  local start, members, at = self.start, self.members, 1
  for k = 1, nreg do
    start[k] = at
    at = at + count[k]
    count[k] = start[k]
  end
  start[nreg + 1] = at
  for i = 1, n do
    local k = regionOf[i]
    members[count[k]] = i
    count[k] = count[k] + 1
  end
  self.nreg = nreg
  return nreg
end

-- The seams a rectangle's faces get when the parts on them are whole faces (shared: a
-- piece's `_seams` is never changed, strike/base/VertexShape.lua)
local WHOLE = { [true] = { [true] = { true, false, true, false }, [false] = { true, false, false, false } },
  [false] = { [true] = { false, false, true, false } } }

-- A face's seam from its parts (pa, pb from parts first to first + count - 1: column pairs
-- along it, increasing), the face running from column c0 to c1 (forward) or from c1 back to
-- c0: false, true (all of it) or the parts as fractions of the face, increasing
-- (strike/base/VertexShape.lua, `_seams`).
local function seam(pa, pb, first, count, c0, c1, forward)
  if count == 0 then return false end
  if count == 1 and pa[first] == c0 and pb[first] == c1 then return true end
  local parts, len = {}, c1 - c0
  if forward then
    for i = 0, count - 1 do
      parts[2 * i + 1], parts[2 * i + 2] = (pa[first + i] - c0) / len, (pb[first + i] - c0) / len
    end
  else
    for i = 0, count - 1 do
      local m = 2 * (count - i)
      parts[m - 1], parts[m] = (c1 - pb[first + i]) / len, (c1 - pa[first + i]) / len
    end
  end
  return parts
end

--- The first rectangle of region k (Builder:rect reads it).
---@param k integer
---@return integer
function Builder:first(k) return self.members[self.start[k]] end

--- The body of region k: a Collider of its rectangles, cell (c, r) spanning x from ox + c gw
--- to ox + (c + 1) gw and y from oy + r gh to oy + (r + 1) gh, where (ox, oy) is the key's
--- offset (offx[key], offy[key]), with the seams between them marked; and its number of tiles.
---@param k integer
---@param offx number[]
---@param offy number[]
---@param gw number
---@param gh number
---@return strike.Collider
---@return integer tiles
function Builder:body(k, offx, offy, gw, gh)
  local members, x0, y0, x1, y1, key = self.members, self.x0, self.y0, self.x1, self.y1, self.key
  local tfirst, tcount, bfirst, bcount, pa, pb = self.tfirst, self.tcount, self.bfirst, self.bcount, self.pa, self.pb
  local from, to = self.start[k], self.start[k + 1] - 1
  local rects, tiles = {}, 0
  for m = from, to do
    local q = members[m]
    local c0, r0, c1, r1, kq = x0[q], y0[q], x1[q], y1[q], key[q]
    local ox, oy = offx[kq], offy[kq]
    tiles = tiles + (c1 - c0) * (r1 - r0)
    local xa, xb, ya, yb = ox + c0 * gw, ox + c1 * gw, oy + r0 * gh, oy + r1 * gh
    local rect = Rectangle((xa + xb) / 2, (ya + yb) / 2, xb - xa, yb - ya)
    local nt, nb = tcount[q], bcount[q]
    if nt > 0 or nb > 0 then
      -- (faces as S.hapes.Rectangle numbers them: 1 the min-y side, running +x; 2 the +x
      -- side; 3 the max-y side, running -x; 4 the -x side. Sides are never seams: two runs
      -- of a row never touch)
      local t = seam(pa, pb, tfirst[q], nt, c0, c1, true)
      local b = seam(pa, pb, bfirst[q], nb, c0, c1, false)
      local whole = type(t) == 'boolean' and type(b) == 'boolean' and WHOLE[t][b]
      rect._seams = whole or { t, false, b, false }
    end
    rects[m - from + 1] = rect
  end
  return Collider._of(rects), tiles
end

--- The rectangle q: its columns c0 to c1 and rows r0 to r1 (ends exclusive) and its key.
---@param q integer
---@return integer c0
---@return integer r0
---@return integer c1
---@return integer r1
---@return integer key
function Builder:rect(q) return self.x0[q], self.y0[q], self.x1[q], self.y1[q], self.key[q] end

return M
