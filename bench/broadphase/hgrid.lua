--- A hierarchical grid broadphase for axis-aligned boxes that sizes itself: no cell size to
--- choose, no world bounds.
---
--- Levels. Level L is a grid of square cells of side 2^L. A box whose larger side is s goes
--- to the level with the smallest cell wider than s (2^L > s, strictly: a rounded width of
--- exactly 2^L may hide a true width a hair above it), and is filed in the one cell that
--- holds its min corner. Two boxes of one level can then only overlap when their cells are
--- neighbours, and a box can only overlap a box of a coarser level M whose min corner lies in
--- the 2 or 3 cells per axis of level M from its own min corner less 2^M to its max corner.
--- So the pairs are: within each cell, against 4 of the 8 neighbouring cells (right, and the
--- three above: each neighbouring pair once), and from each box against every coarser level
--- that holds boxes. This is the hierarchical grid of C. Ericson, Real-Time Collision
--- Detection (2005), 7.2.2 "Hierarchical Grids", with cells hashed instead of stored in a
--- fixed array (7.1.3 "Hashed Storage and Infinite Grids"); the pruning of neighbour cells
--- by the members' actual extents is ours.
---
--- Cells are found through an open-addressing hash table (linear probing, deletion by
--- backward shift) held in one flat array, so that cells appearing and vanishing as boxes
--- move never make Lua rehash a table: nothing is allocated once the arrays have grown. A
--- cell's identity is its level and its coordinates modulo 2^22, so any finite coordinate
--- works; cells 2^22 apart at one level share a bucket, which costs box tests, never
--- correctness (their boxes cannot overlap, and every test is exact). Boxes smaller than
--- 2^-16 (points) go to level -16, unless their distance from the origin asks for a coarser
--- level to keep cell coordinates exact (cells are at least 2^-40 of it).
---
--- Proxies and cells are records in flat number arrays; a cell's members form a list linked
--- through the proxy records. Pairs are packed as a * 2^26 + b and sorted, so their order
--- depends only on the boxes, never on the history of inserts and moves.
---
--- Ids: positive integers, below 2^26. An id is stable until removed; remove frees it, and
--- insert takes the most recently freed id, else the next never-used one (1, 2, 3, ...).
--- Touching boxes overlap (closed intervals). Coordinates must be finite; sizes below 2^100.
local HGrid = {
  _VERSION = 'hgrid 0.1',
  _DESCRIPTION = 'A self-sizing hierarchical grid broadphase for axis-aligned boxes',
  _LICENSE = 'MIT (the strike project)',
}
HGrid.__index = HGrid

local floor, abs, log, huge = math.floor, math.abs, math.log, math.huge
local sort = table.sort

-- Levels: index li = 1 .. NLEVELS is level L = li + MINLEVEL - 1, cell side cell[li] = 2^L.
local MINLEVEL, MAXLEVEL = -16, 100
local NLEVELS = MAXLEVEL - MINLEVEL + 1
local GUARD = 2 ^ -40 -- a cell is at least this fraction of its box's distance from the origin
local LIMIT = 2 ^ MAXLEVEL -- sizes must stay below this
local cell, inv = {}, {}
for li = 1, NLEVELS do
  cell[li] = 2 ^ (li + MINLEVEL - 1)
  inv[li] = 2 ^ -(li + MINLEVEL - 1)
end
local LOG2 = log(2)

-- Proxy records: proxy id's fields are at p[id * PS + field].
local MINX, MINY, MAXX, MAXY = 1, 2, 3, 4
local LEVEL = 5 -- level index, 0 while the id is free
local CX, CY = 6, 7 -- the cell of the min corner (true coordinates, not wrapped)
local CELL = 8 -- the cell record holding the proxy
local NEXT, PREV = 9, 10 -- the cell's member list (0 ends it)
local LOW = 11 -- a box this small or smaller moves to a finer level (-1: never)
local PS = 11

-- Cell records: cell c's fields are at c[c * CS + field].
local CKEY = 1 -- identity: level, x and y modulo WRAP, packed
local CLEVEL, CWX, CWY = 2, 3, 4 -- level index and wrapped coordinates
local CHEAD = 5 -- first member (0: the record is free)
local CPOS = 6 -- index in the list of live cells
local CS = 6

-- The hash table: slot s (0 .. cap - 1) holds a cell key at h[2s + 1] (EMPTY when unused)
-- and the cell record's index at h[2s + 2].
local WRAP = 4194304 -- 2^22
local WRAP2 = WRAP * WRAP
local EMPTY = -1
local K1, K2, K3 = 1664525, 22695477, 40503 -- odd multipliers mixing the parts of a key

local PAIR = 67108864 -- 2^26: pairs are packed as a * PAIR + b

-- Scratch shared by every grid: packed pairs (or query results) to sort, and its length.
local keys, nKeys = {}, 0

--- A new, empty grid.
---@return table grid
function HGrid.new()
  local self = setmetatable({
    p = {}, -- proxy records
    nIds = 0, -- ids ever used
    free = {}, nFree = 0, -- freed ids (a stack)
    nProxies = 0,
    c = {}, -- cell records
    nCellRecs = 0,
    cfree = {}, nCfree = 0, -- free cell records (a stack)
    live = {}, nLive = 0, -- live cells (those with members), in any order
    h = {}, cap = 0, -- the hash table
    perLevel = {}, -- proxies per level index
    levels = {}, nLevels = 0, -- the level indices that hold proxies, ascending
    levelPos = {}, -- level index -> its position in `levels`, or 0
  }, HGrid)
  for li = 1, NLEVELS do
    self.perLevel[li], self.levelPos[li] = 0, 0
  end
  local h, cap = self.h, 61
  for s = 0, cap - 1 do h[2 * s + 1], h[2 * s + 2] = EMPTY, 0 end
  self.cap = cap
  return self
end

-- The home slot of a cell key's parts.
local function home(li, wx, wy, cap)
  return (wx * K1 + wy * K2 + li * K3) % cap
end

-- The cell record of level li holding cell (cx, cy), or 0; then its key, and the slot where
-- the probe ended (the cell's, or the empty one where it would go).
local function find(h, cap, li, cx, cy)
  local wx, wy = cx % WRAP, cy % WRAP
  local key = li * WRAP2 + wx * WRAP + wy
  local s = (wx * K1 + wy * K2 + li * K3) % cap
  local k = h[2 * s + 1]
  while k ~= key do
    if k == EMPTY then return 0, key, s end
    s = s + 1
    if s == cap then s = 0 end
    k = h[2 * s + 1]
  end
  return h[2 * s + 2], key, s
end

local function isPrime(n)
  if n % 2 == 0 then return n == 2 end
  local d = 3
  while d * d <= n do
    if n % d == 0 then return false end
    d = d + 2
  end
  return true
end

-- Grow the hash table to a prime capacity above twice the old one, and refile every live
-- cell (the only allocation of the cell storage: it happens when the table fills, never in
-- a steady state).
local function grow(self)
  local cap = 2 * self.cap + 1
  while not isPrime(cap) do cap = cap + 2 end
  local h, c, live = {}, self.c, self.live
  for s = 0, cap - 1 do h[2 * s + 1], h[2 * s + 2] = EMPTY, 0 end
  for i = 1, self.nLive do
    local cr = live[i]
    local b = cr * CS
    local s = home(c[b + CLEVEL], c[b + CWX], c[b + CWY], cap)
    while h[2 * s + 1] ~= EMPTY do
      s = s + 1
      if s == cap then s = 0 end
    end
    h[2 * s + 1], h[2 * s + 2] = c[b + CKEY], cr
  end
  self.h, self.cap = h, cap
end

-- Remove cell record cr (now without members) from the hash table and the live list.
local function dropCell(self, cr)
  local c, h, cap = self.c, self.h, self.cap
  local b = cr * CS
  local key = c[b + CKEY]
  local i = home(c[b + CLEVEL], c[b + CWX], c[b + CWY], cap)
  while h[2 * i + 1] ~= key do
    i = i + 1
    if i == cap then i = 0 end
  end
  -- Backward shift: pull later entries of the probe run into the hole when their home slot
  -- does not lie cyclically in (hole, entry].
  local j = i
  while true do
    j = j + 1
    if j == cap then j = 0 end
    local k = h[2 * j + 1]
    if k == EMPTY then break end
    local e = h[2 * j + 2] * CS
    local hs = home(c[e + CLEVEL], c[e + CWX], c[e + CWY], cap)
    local stays
    if i <= j then stays = i < hs and hs <= j else stays = i < hs or hs <= j end
    if not stays then
      h[2 * i + 1], h[2 * i + 2] = k, h[2 * j + 2]
      i = j
    end
  end
  h[2 * i + 1], h[2 * i + 2] = EMPTY, 0
  -- out of the live list (the last one takes its place)
  local live, n = self.live, self.nLive
  local pos = c[b + CPOS]
  local last = live[n]
  live[pos] = last
  c[last * CS + CPOS] = pos
  self.nLive = n - 1
  c[b + CHEAD] = 0
  local nf = self.nCfree + 1
  self.cfree[nf], self.nCfree = cr, nf
end

-- File proxy id (its record already holds LEVEL, CX and CY) in its cell, making the cell
-- if it has no members yet.
local function link(self, id)
  local p, c = self.p, self.c
  local pb = id * PS
  local li, cx, cy = p[pb + LEVEL], p[pb + CX], p[pb + CY]
  local cr, key, s = find(self.h, self.cap, li, cx, cy)
  if cr == 0 then
    local nf = self.nCfree
    if nf > 0 then
      cr = self.cfree[nf]
      self.nCfree = nf - 1
    else
      cr = self.nCellRecs + 1
      self.nCellRecs = cr
    end
    local b = cr * CS
    c[b + CKEY], c[b + CLEVEL], c[b + CWX], c[b + CWY], c[b + CHEAD] = key, li, cx % WRAP, cy % WRAP, 0
    local h = self.h
    h[2 * s + 1], h[2 * s + 2] = key, cr
    local n = self.nLive + 1
    self.live[n], self.nLive = cr, n
    c[b + CPOS] = n
    if 2 * n > self.cap then grow(self) end
  end
  local b = cr * CS
  local head = c[b + CHEAD]
  p[pb + CELL], p[pb + NEXT], p[pb + PREV] = cr, head, 0
  if head ~= 0 then p[head * PS + PREV] = id end
  c[b + CHEAD] = id
end

-- Take proxy id out of its cell's member list, dropping the cell when it empties.
local function unlink(self, id)
  local p, c = self.p, self.c
  local pb = id * PS
  local cr, nx, pv = p[pb + CELL], p[pb + NEXT], p[pb + PREV]
  if pv ~= 0 then
    p[pv * PS + NEXT] = nx
  else
    c[cr * CS + CHEAD] = nx
  end
  if nx ~= 0 then p[nx * PS + PREV] = pv end
  if c[cr * CS + CHEAD] == 0 then dropCell(self, cr) end
end

-- The list of levels holding proxies, ascending, rebuilt when a level fills or empties.
local function relist(self)
  local perLevel, levels, levelPos = self.perLevel, self.levels, self.levelPos
  local n = 0
  for li = 1, NLEVELS do
    if perLevel[li] > 0 then
      n = n + 1
      levels[n], levelPos[li] = li, n
    else
      levelPos[li] = 0
    end
  end
  for i = n + 1, self.nLevels do levels[i] = nil end
  self.nLevels = n
end

-- The level index for a box, and the size at or below which it should move to a finer
-- level (-1 when its level was set by the floor or by its distance from the origin).
local function levelOf(minx, miny, maxx, maxy)
  local s = maxx - minx
  if maxy - miny > s then s = maxy - miny end
  local far = abs(minx)
  if abs(maxx) > far then far = abs(maxx) end
  if abs(miny) > far then far = abs(miny) end
  if abs(maxy) > far then far = abs(maxy) end
  far = far * GUARD
  local bySize = true
  if far > s then s, bySize = far, false end
  if s < cell[1] then return 1, -1 end
  local li = floor(log(s) / LOG2) - MINLEVEL + 1
  if li < 1 then li = 1 elseif li > NLEVELS then li = NLEVELS end
  while li < NLEVELS and cell[li] <= s do li = li + 1 end
  while li > 1 and cell[li - 1] > s do li = li - 1 end
  return li, (bySize and li > 1) and cell[li] * 0.25 or -1
end

-- Move a level's proxy count by d, relisting the levels when one fills or empties.
local function countLevel(self, li, d)
  local n = self.perLevel[li] + d
  self.perLevel[li] = n
  if n == 0 or n == d then relist(self) end
end

local function badBox(minx, miny, maxx, maxy)
  return not (maxx - minx < LIMIT and maxy - miny < LIMIT and minx <= maxx and miny <= maxy)
end

local function boxText(minx, miny, maxx, maxy)
  return ('(%s, %s, %s, %s)'):format(tostring(minx), tostring(miny), tostring(maxx), tostring(maxy))
end

--- Add a box; returns its proxy id (see the module's header for how ids are reused).
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@return integer id
function HGrid:insert(minx, miny, maxx, maxy)
  if type(minx) ~= 'number' or type(miny) ~= 'number' or type(maxx) ~= 'number' or type(maxy) ~= 'number'
    or badBox(minx, miny, maxx, maxy) then
    error('hgrid:insert: expected finite numbers minx <= maxx, miny <= maxy, got '
      .. boxText(minx, miny, maxx, maxy), 2)
  end
  local id
  if self.nFree > 0 then
    id = self.free[self.nFree]
    self.nFree = self.nFree - 1
  else
    id = self.nIds + 1
    if id >= PAIR then error('hgrid:insert: too many proxies (ids must stay below 2^26)', 2) end
    self.nIds = id
  end
  local p = self.p
  local b = id * PS
  local li, low = levelOf(minx, miny, maxx, maxy)
  local iv = inv[li]
  p[b + MINX], p[b + MINY], p[b + MAXX], p[b + MAXY] = minx, miny, maxx, maxy
  p[b + LEVEL], p[b + CX], p[b + CY], p[b + LOW] = li, floor(minx * iv), floor(miny * iv), low
  link(self, id)
  countLevel(self, li, 1)
  self.nProxies = self.nProxies + 1
  return id
end

--- Give proxy id its new bounds. Cheap when the box keeps its level and its cell.
---@param id integer
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
function HGrid:update(id, minx, miny, maxx, maxy)
  local p = self.p
  local b = id * PS
  local li = p[b + LEVEL]
  if not li or li == 0 or badBox(minx, miny, maxx, maxy) then
    if not li or li == 0 then error('hgrid:update: no proxy ' .. tostring(id), 2) end
    error('hgrid:update: expected finite numbers minx <= maxx, miny <= maxy, got '
      .. boxText(minx, miny, maxx, maxy), 2)
  end
  p[b + MINX], p[b + MINY], p[b + MAXX], p[b + MAXY] = minx, miny, maxx, maxy
  local s = maxx - minx
  if maxy - miny > s then s = maxy - miny end
  if s < cell[li] and s > p[b + LOW] then
    local iv = inv[li]
    local cx, cy = floor(minx * iv), floor(miny * iv)
    if cx == p[b + CX] and cy == p[b + CY] then return end
    -- a new cell: look at the level again too (the distance from the origin may ask for
    -- a coarser one)
  end
  unlink(self, id)
  local nli, low = levelOf(minx, miny, maxx, maxy)
  if nli ~= li then
    countLevel(self, li, -1)
    countLevel(self, nli, 1)
  end
  local iv = inv[nli]
  p[b + LEVEL], p[b + CX], p[b + CY], p[b + LOW] = nli, floor(minx * iv), floor(miny * iv), low
  link(self, id)
end

--- Remove proxy id; its id becomes free for reuse.
---@param id integer
function HGrid:remove(id)
  local p = self.p
  local b = id * PS
  local li = p[b + LEVEL]
  if not li or li == 0 then error('hgrid:remove: no proxy ' .. tostring(id), 2) end
  unlink(self, id)
  countLevel(self, li, -1)
  p[b + LEVEL] = 0
  local nf = self.nFree + 1
  self.free[nf], self.nFree = id, nf
  self.nProxies = self.nProxies - 1
end

--- The number of proxies.
---@return integer
function HGrid:count()
  return self.nProxies
end

-- Sort keys[1 .. n] (n is the new length: longer old contents are cleared first, so that
-- table.sort, which sorts up to the length, sees exactly n).
local function sortKeys(n)
  for i = n + 1, nKeys do keys[i] = nil end
  nKeys = n
  sort(keys)
end

--- Every pair of proxies whose boxes overlap (touching counts), each once, as a flat list
--- {a1, b1, a2, b2, ...} with a < b, in ascending order of (a, b). Entries of `out` past the
--- 2n written are cleared. Nothing is allocated when `out` is reused (beyond the grid's
--- own scratch growing to the largest count so far).
---@param out table
---@return integer n the number of pairs
function HGrid:pairs(out)
  local p, c, h, cap = self.p, self.c, self.h, self.cap
  local live = self.live
  local levels, nLevels, levelPos = self.levels, self.nLevels, self.levelPos
  local n = 0
  for i = 1, self.nLive do
    local cb = live[i] * CS
    local li = c[cb + CLEVEL]
    local size = cell[li]
    local head = c[cb + CHEAD]
    -- Pairs within the cell; and whether any member reaches into the next cell right or up.
    local right, up = false, false
    local a = head
    while a ~= 0 do
      local ab = a * PS
      local ax0, ay0, ax1, ay1 = p[ab + MINX], p[ab + MINY], p[ab + MAXX], p[ab + MAXY]
      if ax1 >= (p[ab + CX] + 1) * size then right = true end
      if ay1 >= (p[ab + CY] + 1) * size then up = true end
      local bb = p[ab + NEXT]
      while bb ~= 0 do
        local q = bb * PS
        if p[q + MINX] <= ax1 and ax0 <= p[q + MAXX] and p[q + MINY] <= ay1 and ay0 <= p[q + MAXY] then
          n = n + 1
          if a < bb then keys[n] = a * PAIR + bb else keys[n] = bb * PAIR + a end
        end
        bb = p[q + NEXT]
      end
      a = p[ab + NEXT]
    end
    -- Against the neighbouring cells right, up-left, up and up-right (each neighbouring
    -- pair of cells once).
    if right or up then
      local hb = head * PS
      local cx, cy = p[hb + CX], p[hb + CY]
      for k = 1, 4 do
        local nx, ny
        if k == 1 then nx, ny = cx + 1, cy
        elseif k == 2 then nx, ny = cx - 1, cy + 1
        elseif k == 3 then nx, ny = cx, cy + 1
        else nx, ny = cx + 1, cy + 1 end
        if (k == 1 and right) or (k ~= 1 and up and (k ~= 4 or right)) then
          local nr = find(h, cap, li, nx, ny)
          if nr ~= 0 then
            local bb = c[nr * CS + CHEAD]
            while bb ~= 0 do
              local q = bb * PS
              local bx0, by0, bx1, by1 = p[q + MINX], p[q + MINY], p[q + MAXX], p[q + MAXY]
              a = head
              while a ~= 0 do
                local ab = a * PS
                if bx0 <= p[ab + MAXX] and p[ab + MINX] <= bx1 and by0 <= p[ab + MAXY] and p[ab + MINY] <= by1 then
                  n = n + 1
                  if a < bb then keys[n] = a * PAIR + bb else keys[n] = bb * PAIR + a end
                end
                a = p[ab + NEXT]
              end
              bb = p[q + NEXT]
            end
          end
        end
      end
    end
    -- Each member against every coarser level that holds boxes: the cells there whose
    -- boxes (narrower than a cell) can reach it.
    local first = levelPos[li] + 1
    if first <= nLevels then
      a = head
      while a ~= 0 do
        local ab = a * PS
        local ax0, ay0, ax1, ay1 = p[ab + MINX], p[ab + MINY], p[ab + MAXX], p[ab + MAXY]
        for k = first, nLevels do
          local lm = levels[k]
          local iv = inv[lm]
          local gx0, gx1 = floor(ax0 * iv) - 1, floor(ax1 * iv)
          local gy0, gy1 = floor(ay0 * iv) - 1, floor(ay1 * iv)
          for gy = gy0, gy1 do
            for gx = gx0, gx1 do
              local nr = find(h, cap, lm, gx, gy)
              if nr ~= 0 then
                local bb = c[nr * CS + CHEAD]
                while bb ~= 0 do
                  local q = bb * PS
                  if p[q + MINX] <= ax1 and ax0 <= p[q + MAXX] and p[q + MINY] <= ay1 and ay0 <= p[q + MAXY] then
                    n = n + 1
                    if a < bb then keys[n] = a * PAIR + bb else keys[n] = bb * PAIR + a end
                  end
                  bb = p[q + NEXT]
                end
              end
            end
          end
        end
        a = p[ab + NEXT]
      end
    end
  end
  sortKeys(n)
  for i = 1, n do
    local k = keys[i]
    local a = floor(k / PAIR)
    out[2 * i - 1], out[2 * i] = a, k - a * PAIR
  end
  local i = 2 * n + 1
  while out[i] ~= nil do
    out[i] = nil
    i = i + 1
  end
  return n
end

--- The ids of the proxies whose boxes overlap the given box (touching counts), ascending,
--- in out[1 .. k]; entries of `out` past k are cleared. Nothing is allocated when `out` is
--- reused.
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@param out table
---@return integer k
function HGrid:query(minx, miny, maxx, maxy, out)
  if type(minx) ~= 'number' or type(miny) ~= 'number' or type(maxx) ~= 'number' or type(maxy) ~= 'number'
    or not (minx <= maxx and miny <= maxy) then
    error('hgrid:query: expected numbers minx <= maxx, miny <= maxy, got ' .. boxText(minx, miny, maxx, maxy), 2)
  end
  local p, c, h, cap = self.p, self.c, self.h, self.cap
  local levels, nLevels = self.levels, self.nLevels
  local k = 0
  -- The cells to visit; past the number of proxies (or where wrapped cells could repeat),
  -- testing every proxy is cheaper.
  local cells = 0
  for j = 1, nLevels do
    local iv = inv[levels[j]]
    local w, t = floor(maxx * iv) - floor(minx * iv) + 2, floor(maxy * iv) - floor(miny * iv) + 2
    if w >= WRAP or t >= WRAP then cells = huge; break end
    cells = cells + w * t
  end
  if cells > self.nProxies then
    for id = 1, self.nIds do
      local b = id * PS
      local li = p[b + LEVEL]
      if li ~= 0 and p[b + MINX] <= maxx and minx <= p[b + MAXX] and p[b + MINY] <= maxy and miny <= p[b + MAXY] then
        k = k + 1
        keys[k] = id
      end
    end
  else
    for j = 1, nLevels do
      local lm = levels[j]
      local iv = inv[lm]
      for gy = floor(miny * iv) - 1, floor(maxy * iv) do
        for gx = floor(minx * iv) - 1, floor(maxx * iv) do
          local nr = find(h, cap, lm, gx, gy)
          if nr ~= 0 then
            local bb = c[nr * CS + CHEAD]
            while bb ~= 0 do
              local q = bb * PS
              if p[q + MINX] <= maxx and minx <= p[q + MAXX] and p[q + MINY] <= maxy and miny <= p[q + MAXY] then
                k = k + 1
                keys[k] = bb
              end
              bb = p[q + NEXT]
            end
          end
        end
      end
    end
  end
  sortKeys(k)
  for i = 1, k do out[i] = keys[i] end
  local i = k + 1
  while out[i] ~= nil do
    out[i] = nil
    i = i + 1
  end
  return k
end

return HGrid
