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
--- Detection (2005), section 7.2 (Hierarchical Grids), with its cells hashed as in 7.1 (an
--- unbounded grid in a hash table) instead of stored in a fixed array; the pruning of
--- neighbour cells by the members' actual extents is ours.
---
--- Cells are the slots of an open-addressing hash table (linear probing, deletion by
--- backward shift) held in one flat array, so that cells appearing and vanishing as boxes
--- move never make Lua rehash a table: nothing is allocated once the arrays have grown. A
--- cell's identity is its level and its coordinates modulo 2^22, so any finite coordinate
--- works; cells 2^22 apart at one level share a bucket, which costs box tests, never
--- correctness (their boxes cannot overlap, and every test is exact). Boxes smaller than
--- 2^-16 (points) go to level -16, unless their distance from the origin asks for a coarser
--- level to keep cell coordinates exact (cells are at least 2^-40 of it).
---
--- Shaped for LuaJIT: update only notes a box that left its cell (settle, called by pairs
--- and query, refiles them all in one loop of its own), and pairs lists the cells to look
--- up before looking them up in one tight loop. A branch off a loop is compiled as a side
--- trace that must hold every value live there in registers; in the caller's loop, or in
--- one loop doing everything, those are too many and LuaJIT gives up ("register coalescing
--- too complex"), compiling and aborting side traces until it flushes them all.
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

-- Proxy records, the fields that finding pairs reads: proxy id's are at p[id * PS + field].
local MINX, MINY, MAXX, MAXY = 1, 2, 3, 4
local NEXT = 5 -- the next member of its cell (0 ends the list)
local CX, CY = 6, 7 -- the cell of the min corner (true coordinates, not wrapped)
local LEVEL = 8 -- its level index; negated when the box may not move to a finer level
-- (set by the floor or by its distance from the origin); 0 while the id is free
local PS = 8
-- The other fields, at q[id * QS + field].
local CELL = 1 -- its cell record
local PREV = 2 -- the previous member of its cell (0: it is the first)
local PENDING = 3 -- 1 while it waits in the moved list to be refiled, else 0
local QS = 3

-- Cell records, at c[cr * CS + field]: where the cell is in the hash table, and what its
-- home slot is computed from.
local CSLOT, CLEVEL, CWX, CWY = 1, 2, 3, 4
local CS = 4

-- The hash table: slot s (0 .. cap + TAIL - 1) holds a cell's key at h[3s + 1] (EMPTY when the slot
-- is unused), its first member at h[3s + 2] (0 when unused) and its record at h[3s + 3]. A
-- key packs the level index and the cell's coordinates modulo WRAP.
local WRAP = 4194304 -- 2^22
local WRAP2 = WRAP * WRAP
local EMPTY = -1
local K1, K2, K3 = 1664525, 22695477, 40503 -- odd multipliers mixing the parts of a key
local LOAD = 0.5 -- the table grows past this share of used slots
-- Every cell lies fewer than WINDOW slots after its home slot (the table grows when an
-- insertion finds no room there), so a lookup probes at most WINDOW slots; it stops at an
-- empty one (deletion shifts later entries back, leaving no hole inside a run). Home slots
-- are 0 .. cap - 1 and probes run on into the TAIL slots after them, never wrapping round.
local WINDOW = 8
local TAIL = WINDOW

local PAIR = 67108864 -- 2^26: pairs are packed as a * PAIR + b

-- Scratch shared by every grid: packed pairs (or query results) to sort, and its length.
local keys, nKeys = {}, 0

local function clearSlots(h, cap)
  for s = 0, cap + TAIL - 1 do h[3 * s + 1], h[3 * s + 2], h[3 * s + 3] = EMPTY, 0, 0 end
end

--- A new, empty grid.
---@return table grid
function HGrid.new()
  local self = setmetatable({
    p = {}, q = {}, -- proxy records
    nIds = 0, -- ids ever used
    free = {}, nFree = 0, -- freed ids (a stack)
    moved = {}, nMoved = 0, -- ids whose cell or level changed since the last settle
    nProxies = 0,
    c = {}, -- cell records
    nCellRecs = 0,
    cfree = {}, nCfree = 0, -- free cell records (a stack)
    nCells = 0, -- cells with members
    h = {}, cap = 61, -- the hash table
    perLevel = {}, -- proxies per level index
    levels = {}, nLevels = 0, -- the level indices that hold proxies, ascending
    levelPos = {}, -- level index -> its position in `levels`, or 0
  }, HGrid)
  for li = 1, NLEVELS do
    self.perLevel[li], self.levelPos[li] = 0, 0
  end
  clearSlots(self.h, self.cap)
  return self
end

-- The home slot of a cell key's parts.
local function home(li, wx, wy, cap)
  return (wx * K1 + wy * K2 + li * K3) % cap
end

-- The slot of the cell with this key, probing from slot s: the cell's slot when it has
-- members, else -1 - the empty slot that ends the probe run.
local function probe(h, key, s)
  local k = h[3 * s + 1]
  while k ~= key and k ~= EMPTY do
    s = s + 1
    k = h[3 * s + 1]
  end
  if k == EMPTY then return -1 - s end
  return s
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

local function nextPrime(n)
  if n % 2 == 0 then n = n + 1 end
  while not isPrime(n) do n = n + 2 end
  return n
end

-- Refile every cell of the hash table into a new one of capacity cap; false (and nothing
-- changed) if a cell would land WINDOW slots or more from its home.
local function refile(self, cap)
  local old, oldCap, c = self.h, self.cap, self.c
  local h = {}
  clearSlots(h, cap)
  for t = 0, oldCap + TAIL - 1 do
    local cr = old[3 * t + 3]
    if old[3 * t + 1] ~= EMPTY then
      local s0 = home(c[cr * CS + CLEVEL], c[cr * CS + CWX], c[cr * CS + CWY], cap)
      local s = s0
      while h[3 * s + 1] ~= EMPTY do s = s + 1 end
      if s - s0 >= WINDOW then return false end
      h[3 * s + 1], h[3 * s + 2], h[3 * s + 3] = old[3 * t + 1], old[3 * t + 2], cr
    end
  end
  for s = 0, cap + TAIL - 1 do
    if h[3 * s + 1] ~= EMPTY then c[h[3 * s + 3] * CS + CSLOT] = s end
  end
  self.h, self.cap = h, cap
  return true
end

-- Grow the hash table to a prime capacity above twice the old one (the only allocation of
-- the cell storage: it happens when the table fills, never in a steady state).
local function grow(self)
  local cap = nextPrime(2 * self.cap + 1)
  while not refile(self, cap) do cap = nextPrime(2 * cap + 1) end
end

-- Remove cell record cr (now without members) and its slot.
local function dropCell(self, cr)
  local c, h, cap = self.c, self.h, self.cap
  local i = c[cr * CS + CSLOT]
  -- Backward shift: pull each later entry of the probe run into the hole when its home slot
  -- is at or before the hole.
  local j = i + 1
  local k = h[3 * j + 1]
  while k ~= EMPTY and j - i < WINDOW do
    local er = h[3 * j + 3]
    local e = er * CS
    if home(c[e + CLEVEL], c[e + CWX], c[e + CWY], cap) <= i then
      h[3 * i + 1], h[3 * i + 2], h[3 * i + 3] = k, h[3 * j + 2], er
      c[e + CSLOT] = i
      i = j
    end
    j = j + 1
    k = h[3 * j + 1]
  end
  h[3 * i + 1], h[3 * i + 2], h[3 * i + 3] = EMPTY, 0, 0
  self.nCells = self.nCells - 1
  local nf = self.nCfree + 1
  self.cfree[nf], self.nCfree = cr, nf
end

-- File proxy id (its record already holds LEVEL, CX and CY) in its cell, making the cell
-- if it has no members yet.
local function link(self, id)
  local p, q, c = self.p, self.q, self.c
  local pb = id * PS
  local li, cx, cy = p[pb + LEVEL], p[pb + CX], p[pb + CY]
  if li < 0 then li = -li end
  local wx, wy = cx % WRAP, cy % WRAP
  local key = li * WRAP2 + wx * WRAP + wy
  local s0 = home(li, wx, wy, self.cap)
  local s = probe(self.h, key, s0)
  local cr
  if s < 0 then
    while self.nCells + 1 > LOAD * self.cap or -1 - s - s0 >= WINDOW do
      grow(self)
      s0 = home(li, wx, wy, self.cap)
      s = probe(self.h, key, s0)
    end
    s = -1 - s
    local nf = self.nCfree
    if nf > 0 then
      cr = self.cfree[nf]
      self.nCfree = nf - 1
    else
      cr = self.nCellRecs + 1
      self.nCellRecs = cr
    end
    local b = cr * CS
    c[b + CSLOT], c[b + CLEVEL], c[b + CWX], c[b + CWY] = s, li, wx, wy
    local h = self.h
    h[3 * s + 1], h[3 * s + 2], h[3 * s + 3] = key, 0, cr
    self.nCells = self.nCells + 1
  else
    cr = self.h[3 * s + 3]
  end
  local h = self.h
  local head = h[3 * s + 2]
  p[pb + NEXT] = head
  q[id * QS + CELL], q[id * QS + PREV] = cr, 0
  if head ~= 0 then q[head * QS + PREV] = id end
  h[3 * s + 2] = id
end

-- Take proxy id out of its cell's member list, dropping the cell when it empties.
local function unlink(self, id)
  local p, q = self.p, self.q
  local cr, pv = q[id * QS + CELL], q[id * QS + PREV]
  local nx = p[id * PS + NEXT]
  if pv ~= 0 then
    p[pv * PS + NEXT] = nx
  else
    local s = self.c[cr * CS + CSLOT]
    self.h[3 * s + 2] = nx
    if nx == 0 then dropCell(self, cr) end
  end
  if nx ~= 0 then q[nx * QS + PREV] = pv end
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

-- The level index for a box, negated when the box may not later move to a finer one (its
-- level was set by the floor or by its distance from the origin).
local function levelOf(minx, miny, maxx, maxy)
  local s = maxx - minx
  if maxy - miny > s then s = maxy - miny end
  local far = abs(minx)
  if abs(maxx) > far then far = abs(maxx) end
  if abs(miny) > far then far = abs(miny) end
  if abs(maxy) > far then far = abs(maxy) end
  far = far * GUARD
  local sign = 1
  if far > s then s, sign = far, -1 end
  if s < cell[1] then return -1 end
  local li = floor(log(s) / LOG2) - MINLEVEL + 1
  if li < 1 then li = 1 elseif li > NLEVELS then li = NLEVELS end
  while li < NLEVELS and cell[li] <= s do li = li + 1 end
  while li > 1 and cell[li - 1] > s do li = li - 1 end
  if li == 1 then sign = -1 end
  return sign * li
end

-- Move a level's proxy count by d, relisting the levels when one fills or empties.
local function countLevel(self, li, d)
  if li < 0 then li = -li end
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

-- Put proxy id, whose bounds have changed, in the cell and level they now ask for.
local function refileProxy(self, id)
  local p = self.p
  local b = id * PS
  local minx, miny, maxx, maxy = p[b + MINX], p[b + MINY], p[b + MAXX], p[b + MAXY]
  unlink(self, id)
  local sl, nsl = p[b + LEVEL], levelOf(minx, miny, maxx, maxy)
  if nsl ~= sl then
    countLevel(self, sl, -1)
    countLevel(self, nsl, 1)
  end
  local iv = inv[nsl < 0 and -nsl or nsl]
  p[b + LEVEL], p[b + CX], p[b + CY] = nsl, floor(minx * iv), floor(miny * iv)
  link(self, id)
end

--- Refile the proxies that have left their cells since the last call. pairs and query do
--- it first; there is no need to call it, except to choose when the work is done.
function HGrid:settle()
  local q, moved = self.q, self.moved
  for i = 1, self.nMoved do
    local id = moved[i]
    if q[id * QS + PENDING] == 1 then
      q[id * QS + PENDING] = 0
      refileProxy(self, id)
    end
  end
  self.nMoved = 0
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
  local sl = levelOf(minx, miny, maxx, maxy)
  local iv = inv[sl < 0 and -sl or sl]
  p[b + MINX], p[b + MINY], p[b + MAXX], p[b + MAXY] = minx, miny, maxx, maxy
  p[b + LEVEL], p[b + CX], p[b + CY] = sl, floor(minx * iv), floor(miny * iv)
  self.q[id * QS + PENDING] = 0
  link(self, id)
  countLevel(self, sl, 1)
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
  local sl = p[b + LEVEL]
  if not sl or sl == 0 or badBox(minx, miny, maxx, maxy) then
    if not sl or sl == 0 then error('hgrid:update: no proxy ' .. tostring(id), 2) end
    error('hgrid:update: expected finite numbers minx <= maxx, miny <= maxy, got '
      .. boxText(minx, miny, maxx, maxy), 2)
  end
  p[b + MINX], p[b + MINY], p[b + MAXX], p[b + MAXY] = minx, miny, maxx, maxy
  local s = maxx - minx
  if maxy - miny > s then s = maxy - miny end
  local li, low = sl, -1
  if li < 0 then li = -li else low = cell[li] * 0.25 end
  if s < cell[li] and s > low then
    local iv = inv[li]
    if floor(minx * iv) == p[b + CX] and floor(miny * iv) == p[b + CY] then return end
    -- a new cell: look at the level again too (the distance from the origin may ask for
    -- a coarser one)
  end
  -- Refiled later, in settle: its own loop, compiled apart from the caller's (LuaJIT's side
  -- traces from the caller's loop inherit every value live there, and too many of them
  -- make it give up compiling). Until then it stays in its old cell's list.
  local q = self.q
  if q[id * QS + PENDING] == 0 then
    q[id * QS + PENDING] = 1
    local n = self.nMoved + 1
    self.moved[n], self.nMoved = id, n
    if n > 2 * self.nIds + 16 then self:settle() end -- (stale entries from removes)
  end
end

--- Remove proxy id; its id becomes free for reuse.
---@param id integer
function HGrid:remove(id)
  local p = self.p
  local b = id * PS
  local sl = p[b + LEVEL]
  if not sl or sl == 0 then error('hgrid:remove: no proxy ' .. tostring(id), 2) end
  unlink(self, id)
  countLevel(self, sl, -1)
  p[b + LEVEL] = 0
  self.q[id * QS + PENDING] = 0 -- (settle skips its entry in the moved list)
  local nf = self.nFree + 1
  self.free[nf], self.nFree = id, nf
  self.nProxies = self.nProxies - 1
end

--- The number of proxies.
---@return integer
function HGrid:count()
  return self.nProxies
end

-- Finding pairs runs in passes, each a loop of its own with few values live: LuaJIT
-- compiles a branch taken off a loop as a side trace that must hold every value live there
-- in registers at once, and gives up ("register coalescing too complex") when they are too
-- many. So cells to look up are first listed as requests (whose boxes: a cell's members,
-- from their first, or one box, negated; and the key and home slot of the cell wanted),
-- then looked up in one tight loop, then their pairs tested.
local rqWho, rqKey, rqHome = {}, {}, {}

-- Add a request for level li's cell (cx, cy) on behalf of `who`; the new count.
local function request(r, who, li, cx, cy, cap)
  local wx, wy = cx % WRAP, cy % WRAP
  r = r + 1
  rqWho[r], rqKey[r], rqHome[r] = who, li * WRAP2 + wx * WRAP + wy, (wx * K1 + wy * K2 + li * K3) % cap
  return r
end

-- Look every request up, leaving in rqKey the first member of the cell found, or 0.
local function resolve(h, nr)
  for r = 1, nr do
    local s = probe(h, rqKey[r], rqHome[r])
    rqKey[r] = s >= 0 and h[3 * s + 2] or 0
  end
end

-- Pairs among the members of one cell (from `head`), appended to keys[n + 1 ..]; the new n.
local function within(p, head, n)
  local a = head
  while a ~= 0 do
    local ab = a * PS
    local bb = p[ab + NEXT]
    while bb ~= 0 do
      local qb = bb * PS
      if p[qb + MINX] <= p[ab + MAXX] and p[ab + MINX] <= p[qb + MAXX] and p[qb + MINY] <= p[ab + MAXY]
        and p[ab + MINY] <= p[qb + MAXY] then
        n = n + 1
        if a < bb then keys[n] = a * PAIR + bb else keys[n] = bb * PAIR + a end
      end
      bb = p[qb + NEXT]
    end
    a = p[ab + NEXT]
  end
  return n
end

-- Whether some member of a cell reaches the next cell right (1), up (2) or both (3).
local function reaches(p, head, size)
  local r = 0
  local a = head
  while a ~= 0 do
    local ab = a * PS
    if r % 2 == 0 and p[ab + MAXX] >= (p[ab + CX] + 1) * size then r = r + 1 end
    if r < 2 and p[ab + MAXY] >= (p[ab + CY] + 1) * size then r = r + 2 end
    a = p[ab + NEXT]
  end
  return r
end

-- Pairs between box a and the members of a cell (from `other`); the new n.
local function against(p, a, other, n)
  local ab = a * PS
  local x0, y0, x1, y1 = p[ab + MINX], p[ab + MINY], p[ab + MAXX], p[ab + MAXY]
  local bb = other
  while bb ~= 0 do
    local qb = bb * PS
    if p[qb + MINX] <= x1 and x0 <= p[qb + MAXX] and p[qb + MINY] <= y1 and y0 <= p[qb + MAXY] then
      n = n + 1
      if a < bb then keys[n] = a * PAIR + bb else keys[n] = bb * PAIR + a end
    end
    bb = p[qb + NEXT]
  end
  return n
end

-- Pairs between the members of two cells; the new n.
local function across(p, head, other, n)
  local a = head
  while a ~= 0 do
    n = against(p, a, other, n)
    a = p[a * PS + NEXT]
  end
  return n
end

-- The requests for the neighbouring cells of head's cell that its members reach: right,
-- up-left, up and up-right (each neighbouring pair of cells once); the new count.
local function neighbours(p, head, r, cap)
  local hb = head * PS
  local li = p[hb + LEVEL]
  if li < 0 then li = -li end
  local reach = reaches(p, head, cell[li])
  if reach == 0 then return r end
  local cx, cy = p[hb + CX], p[hb + CY]
  if reach ~= 2 then r = request(r, head, li, cx + 1, cy, cap) end
  if reach >= 2 then
    r = request(r, head, li, cx - 1, cy + 1, cap)
    r = request(r, head, li, cx, cy + 1, cap)
    if reach == 3 then r = request(r, head, li, cx + 1, cy + 1, cap) end
  end
  return r
end

-- The requests for the cells of coarser level lm whose boxes (narrower than a cell there)
-- can reach box a; the new count.
local function coarser(p, a, lm, r, cap)
  local ab = a * PS
  local iv = inv[lm]
  local gx0, gx1 = floor(p[ab + MINX] * iv) - 1, floor(p[ab + MAXX] * iv)
  for gy = floor(p[ab + MINY] * iv) - 1, floor(p[ab + MAXY] * iv) do
    for gx = gx0, gx1 do r = request(r, -a, lm, gx, gy, cap) end
  end
  return r
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
  if self.nMoved > 0 then self:settle() end
  local p, h, cap = self.p, self.h, self.cap
  local n, r = 0, 0
  -- Within each cell; and requests for the neighbouring cells of the same level.
  for slot = 0, cap + TAIL - 1 do
    local head = h[3 * slot + 2]
    if head ~= 0 then
      n = within(p, head, n)
      r = neighbours(p, head, r, cap)
    end
  end
  -- Requests for the cells of every coarser level that holds boxes, for each box.
  local levels, nLevels, levelPos = self.levels, self.nLevels, self.levelPos
  if nLevels > 1 then
    local last = levels[nLevels]
    for a = 1, self.nIds do
      local li = p[a * PS + LEVEL]
      if li < 0 then li = -li end
      if li ~= 0 and li ~= last then
        for k = levelPos[li] + 1, nLevels do r = coarser(p, a, levels[k], r, cap) end
      end
    end
  end
  resolve(h, r)
  for i = 1, r do
    local other = rqKey[i]
    if other ~= 0 then
      local who = rqWho[i]
      if who > 0 then n = across(p, who, other, n) else n = against(p, -who, other, n) end
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
  if self.nMoved > 0 then self:settle() end
  local p, h, cap = self.p, self.h, self.cap
  local levels, nLevels = self.levels, self.nLevels
  local k = 0
  -- The cells to visit; past the number of proxies (or where wrapped cells could repeat),
  -- testing every proxy is cheaper.
  local cells = 0
  for j = 1, nLevels do
    local iv = inv[levels[j]]
    local w, t = floor(maxx * iv) - floor(minx * iv) + 2, floor(maxy * iv) - floor(miny * iv) + 2
    if w >= WRAP or t >= WRAP then
      cells = huge
      break
    end
    cells = cells + w * t
  end
  if cells > self.nProxies then
    for id = 1, self.nIds do
      local b = id * PS
      if p[b + LEVEL] ~= 0 and p[b + MINX] <= maxx and minx <= p[b + MAXX] and p[b + MINY] <= maxy
        and miny <= p[b + MAXY] then
        k = k + 1
        keys[k] = id
      end
    end
  else
    local r = 0
    for j = 1, nLevels do
      local lm = levels[j]
      local iv = inv[lm]
      for gy = floor(miny * iv) - 1, floor(maxy * iv) do
        for gx = floor(minx * iv) - 1, floor(maxx * iv) do r = request(r, 0, lm, gx, gy, cap) end
      end
    end
    resolve(h, r)
    for i = 1, r do
      local bb = rqKey[i]
      while bb ~= 0 do
        local qb = bb * PS
        if p[qb + MINX] <= maxx and minx <= p[qb + MAXX] and p[qb + MINY] <= maxy and miny <= p[qb + MAXY] then
          k = k + 1
          keys[k] = bb
        end
        bb = p[qb + NEXT]
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
