--- A dynamic AABB tree broadphase: candidate 1 for the world's broadphase (S.pace).
---
--- Design (ideas from Box2D's b2DynamicTree, E. Catto, v2.4 and v3; no code taken):
--- * A binary tree whose leaves hold one proxy each, stored in flat number arrays indexed
---   by node (parent, two children, height, box, proxy id) with a free list of nodes.
--- * Each leaf holds a fat box: the proxy's exact box grown by a margin of (w + h) / 8 on
---   every side (an eighth of the box's perimeter over 2: 2-7 px for 8-28 px bodies,
---   0.125 px for a 1 px bullet, about 250 px for a 2,000 px platform, nothing for a point),
---   then stretched ahead along the last displacement by 4 times that displacement, at most
---   w + h per axis (so a teleport does not leave a huge box behind). Margins scale with
---   each box, so nothing depends on units or on the distance from the origin. Moving a box
---   inside its fat box costs a few comparisons; leaving it reinserts the leaf.
--- * Insertion walks down choosing the child whose enlarged perimeter, plus the growth it
---   causes in every ancestor, costs least (a surface-area heuristic in 2D, after Box2D
---   v2.4's InsertLeaf), and every insertion or removal rebalances its path to the root by
---   AVL-like rotations (after Box2D v2.4's Balance), so the tree stays about log2(n) deep.
--- * Pairs are kept, not searched for every frame: the tree keeps the set of pairs whose fat
---   boxes overlap (Box2D's pair set). A proxy that leaves its fat box drops its pairs,
---   queries the tree with its new fat box and links what it finds (Box2D's move buffer,
---   done at once). `pairs` then tests the exact boxes of those candidates only, which
---   costs O(n + candidates) per frame however many bodies moved.
---   Each proxy's candidates are a per-proxy array of (partner, position of the back entry
---   in the partner's array), so a pair is unlinked from both sides in O(1).
--- * Results are sorted (ids ascending), so they never depend on insertion history.
---
--- Ids: positive integers, stable until removed; a removed id is reused, lowest free first.
--- Boxes are closed: boxes that touch overlap. Nothing is allocated per call once the
--- arrays have grown to the world's size (n proxies, their candidates, the largest result).
local Tree = {}
Tree.__index = Tree

local min, max = math.min, math.max

--- Fat margin on each side, as a fraction of the box's width + height.
local MARGIN = 0.125
--- The fat box reaches this many displacements ahead of the box...
local PREDICT = 4
--- ...but at most this fraction of the box's width + height, per axis.
local PREDICT_LIMIT = 1
--- Sorts up to this many entries by insertion, longer ones by heapsort.
local SHORT_SORT = 12

--- A new, empty tree.
---@return table
function Tree.new()
  return setmetatable({
    -- nodes: 0 is "none"; a leaf has child1 == 0 and height 0
    parent = {}, child1 = {}, child2 = {}, height = {}, proxyOf = {},
    nx0 = {}, ny0 = {}, nx1 = {}, ny1 = {}, -- fat boxes (unions of children for inner nodes)
    root = 0, nodeTop = 0, freeNode = 0,
    -- proxies: leaf node (0 when free), exact box, candidates (nbr[id][2k-1] the partner,
    -- nbr[id][2k] where the back entry sits in the partner's array), their count
    leaf = {}, px0 = {}, py0 = {}, px1 = {}, py1 = {}, nbr = {}, deg = {},
    idTop = 0, live = 0,
    freeIds = {}, nFreeIds = 0, -- a binary min-heap of free ids
    stack = {}, seg = {}, -- scratch
  }, Tree)
end

------------------------------------------------------------------ sorting (no allocation)

-- Heapsort's step: move t[root] down the max-heap t[root..last] to its place.
local function sift(t, root, last)
  local v = t[root]
  while true do
    local c = 2 * root
    if c > last then break end
    if c < last and t[c + 1] > t[c] then c = c + 1 end
    if t[c] <= v then break end
    t[root] = t[c]
    root = c
  end
  t[root] = v
end

-- Sort t[1..n] ascending: insertion sort when short, else heapsort (in place).
local function sortRange(t, n)
  if n <= SHORT_SORT then
    for i = 2, n do
      local v, j = t[i], i - 1
      while j >= 1 and t[j] > v do
        t[j + 1] = t[j]
        j = j - 1
      end
      t[j + 1] = v
    end
    return
  end
  for i = (n - n % 2) / 2, 1, -1 do sift(t, i, n) end
  for last = n, 2, -1 do
    t[1], t[last] = t[last], t[1]
    sift(t, 1, last - 1)
  end
end

------------------------------------------------------------------ ids: lowest free first

local function takeId(self)
  local h, n = self.freeIds, self.nFreeIds
  if n == 0 then
    local id = self.idTop + 1
    self.idTop = id
    return id
  end
  local id, v = h[1], h[n]
  n = n - 1
  self.nFreeIds = n
  local i = 1
  while true do -- sift v down from the root
    local c = 2 * i
    if c > n then break end
    if c < n and h[c + 1] < h[c] then c = c + 1 end
    if h[c] >= v then break end
    h[i] = h[c]
    i = c
  end
  if n > 0 then h[i] = v end
  return id
end

local function giveId(self, id)
  local h, i = self.freeIds, self.nFreeIds + 1
  self.nFreeIds = i
  while i > 1 do -- sift up
    local p = (i - i % 2) / 2
    if h[p] <= id then break end
    h[i] = h[p]
    i = p
  end
  h[i] = id
end

------------------------------------------------------------------ nodes

local function newNode(self)
  local n = self.freeNode
  if n ~= 0 then
    self.freeNode = self.parent[n] -- the free list is threaded through `parent`
  else
    n = self.nodeTop + 1
    self.nodeTop = n
  end
  self.parent[n], self.child1[n], self.child2[n], self.height[n], self.proxyOf[n] = 0, 0, 0, 0, 0
  return n
end

local function freeNode(self, n)
  self.parent[n], self.child1[n], self.height[n] = self.freeNode, 0, -1
  self.freeNode = n
end

-- Recompute an inner node's box and height from its children.
local function refit(self, n)
  local c1, c2 = self.child1, self.child2
  local x0, y0, x1, y1, h = self.nx0, self.ny0, self.nx1, self.ny1, self.height
  local a, b = c1[n], c2[n]
  x0[n], y0[n] = min(x0[a], x0[b]), min(y0[a], y0[b])
  x1[n], y1[n] = max(x1[a], x1[b]), max(y1[a], y1[b])
  h[n] = 1 + max(h[a], h[b])
end

-- Node a's child c is taller than its sibling by 2 or more: c takes a's place, keeps its
-- taller child, and hands the shorter one to a in c's old slot. Returns c.
--
--        a                c
--       / \              / \
--      b   c     ->     a   f      (f the taller of f, g)
--         / \          / \
--        f   g        b   g
local function rotateUp(self, a, c)
  local parent, c1, c2, h = self.parent, self.child1, self.child2, self.height
  local f, g = c1[c], c2[c]
  if h[g] > h[f] then f, g = g, f end
  local p = parent[a]
  parent[c] = p
  if p == 0 then
    self.root = c
  elseif c1[p] == a then
    c1[p] = c
  else
    c2[p] = c
  end
  c1[c], c2[c] = a, f
  parent[a] = c
  if c1[a] == c then c1[a] = g else c2[a] = g end
  parent[g] = a
  refit(self, a)
  return c
end

-- Rebalance and refit every node from n up to the root.
local function fixUp(self, n)
  local parent, c1, c2, h = self.parent, self.child1, self.child2, self.height
  while n ~= 0 do
    local a, b = c1[n], c2[n]
    local d = h[b] - h[a]
    if d > 1 then
      n = rotateUp(self, n, b)
    elseif d < -1 then
      n = rotateUp(self, n, a)
    end
    refit(self, n)
    n = parent[n]
  end
end

-- Half perimeter of the union of nodes a and b's boxes.
local function unionCost(self, a, b)
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  return max(x1[a], x1[b]) - min(x0[a], x0[b]) + max(y1[a], y1[b]) - min(y0[a], y0[b])
end

-- Put leaf into the tree: descend to the sibling whose pairing costs least, where the cost
-- of stopping at node n is twice the half perimeter of n + leaf (the new parent and the
-- enlarged ancestors), and going down to child c adds the growth of c (its enlarged half
-- perimeter, less its own if c is an inner node whose cost is already counted) to the
-- growth n passes on to its ancestors.
local function insertLeaf(self, leaf)
  if self.root == 0 then
    self.root = leaf
    self.parent[leaf] = 0
    return
  end
  local parent, c1, c2 = self.parent, self.child1, self.child2
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local n = self.root
  while c1[n] ~= 0 do
    local a, b = c1[n], c2[n]
    local combined = unionCost(self, n, leaf)
    local cost = 2 * combined
    local inherit = 2 * (combined - (x1[n] - x0[n] + y1[n] - y0[n]))
    local costA = unionCost(self, a, leaf) + inherit
    if c1[a] ~= 0 then costA = costA - (x1[a] - x0[a] + y1[a] - y0[a]) end
    local costB = unionCost(self, b, leaf) + inherit
    if c1[b] ~= 0 then costB = costB - (x1[b] - x0[b] + y1[b] - y0[b]) end
    if cost < costA and cost < costB then break end
    if costB < costA then n = b else n = a end
  end
  local old = parent[n]
  local p = newNode(self)
  parent[p], c1[p], c2[p] = old, n, leaf
  parent[n], parent[leaf] = p, p
  if old == 0 then
    self.root = p
  elseif c1[old] == n then
    c1[old] = p
  else
    c2[old] = p
  end
  fixUp(self, p)
end

local function removeLeaf(self, leaf)
  if leaf == self.root then
    self.root = 0
    return
  end
  local parent, c1, c2 = self.parent, self.child1, self.child2
  local p = parent[leaf]
  local g = parent[p]
  local sibling = c1[p] == leaf and c2[p] or c1[p]
  freeNode(self, p)
  parent[sibling] = g
  if g == 0 then
    self.root = sibling
    return
  end
  if c1[g] == p then c1[g] = sibling else c2[g] = sibling end
  fixUp(self, g)
end

------------------------------------------------------------------ candidate pairs

local function link(self, i, j)
  local nbr, deg = self.nbr, self.deg
  local di, dj = deg[i] + 1, deg[j] + 1
  local li, lj = nbr[i], nbr[j]
  li[2 * di - 1], li[2 * di] = j, dj
  lj[2 * dj - 1], lj[2 * dj] = i, di
  deg[i], deg[j] = di, dj
end

-- Drop every candidate of proxy i, from both sides.
local function unlinkAll(self, i)
  local nbr, deg = self.nbr, self.deg
  local li = nbr[i]
  for k = 1, 2 * deg[i], 2 do
    local j, at = li[k], li[k + 1]
    local lj, last = nbr[j], deg[j]
    if at ~= last then -- move j's last entry into the hole, and tell its partner
      local m, back = lj[2 * last - 1], lj[2 * last]
      lj[2 * at - 1], lj[2 * at] = m, back
      nbr[m][2 * back] = at
    end
    deg[j] = last - 1
  end
  deg[i] = 0
end

-- Link proxy i with every other proxy whose fat box overlaps its (new) fat box.
local function linkAll(self, i)
  local leaf = self.leaf[i]
  local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local qx0, qy0, qx1, qy1 = x0[leaf], y0[leaf], x1[leaf], y1[leaf]
  local stack, top = self.stack, 1
  stack[1] = self.root
  while top > 0 do
    local n = stack[top]
    top = top - 1
    if x0[n] <= qx1 and x1[n] >= qx0 and y0[n] <= qy1 and y1[n] >= qy0 then
      local a = c1[n]
      if a == 0 then
        if n ~= leaf then link(self, i, proxyOf[n]) end
      else
        stack[top + 1], stack[top + 2] = a, c2[n]
        top = top + 2
      end
    end
  end
end

------------------------------------------------------------------ public API

local function checkBox(fn, minx, miny, maxx, maxy)
  if not (minx <= maxx and miny <= maxy) then -- (false for NaN too)
    error(('tree.%s: expected minx <= maxx and miny <= maxy, got %s, %s, %s, %s'):format(
      fn, tostring(minx), tostring(miny), tostring(maxx), tostring(maxy)), 3)
  end
end

local function checkId(self, fn, id)
  local leaf = self.leaf[id]
  if not leaf or leaf == 0 then
    error(('tree.%s: expected the id of a proxy in this tree, got %s'):format(fn, tostring(id)), 3)
  end
  return leaf
end

-- Give leaf the fat box of its proxy's exact box moved by (dx, dy) since last time.
local function fatten(self, leaf, minx, miny, maxx, maxy, dx, dy)
  local s = (maxx - minx) + (maxy - miny)
  local m = s * MARGIN
  local x0, y0, x1, y1 = minx - m, miny - m, maxx + m, maxy + m
  local limit = s * PREDICT_LIMIT
  dx, dy = dx * PREDICT, dy * PREDICT
  if dx > limit then dx = limit elseif dx < -limit then dx = -limit end
  if dy > limit then dy = limit elseif dy < -limit then dy = -limit end
  if dx > 0 then x1 = x1 + dx else x0 = x0 + dx end
  if dy > 0 then y1 = y1 + dy else y0 = y0 + dy end
  self.nx0[leaf], self.ny0[leaf], self.nx1[leaf], self.ny1[leaf] = x0, y0, x1, y1
end

--- Add a proxy for the box (closed: a box of zero size is a point or a segment).
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@return integer id positive, stable until removed; the lowest free id is reused first
function Tree:insert(minx, miny, maxx, maxy)
  checkBox('insert', minx, miny, maxx, maxy)
  local id = takeId(self)
  if not self.nbr[id] then self.nbr[id] = {} end
  self.deg[id] = 0
  self.px0[id], self.py0[id], self.px1[id], self.py1[id] = minx, miny, maxx, maxy
  local leaf = newNode(self)
  self.leaf[id], self.proxyOf[leaf] = leaf, id
  fatten(self, leaf, minx, miny, maxx, maxy, 0, 0)
  insertLeaf(self, leaf)
  linkAll(self, id)
  self.live = self.live + 1
  return id
end

--- Give a proxy its new exact box. Cheap while the box stays inside its fat box.
---@param id integer
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
function Tree:update(id, minx, miny, maxx, maxy)
  local leaf = checkId(self, 'update', id)
  checkBox('update', minx, miny, maxx, maxy)
  local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
  local dx = (minx + maxx - px0[id] - px1[id]) * 0.5
  local dy = (miny + maxy - py0[id] - py1[id]) * 0.5
  px0[id], py0[id], px1[id], py1[id] = minx, miny, maxx, maxy
  if minx >= self.nx0[leaf] and miny >= self.ny0[leaf] and maxx <= self.nx1[leaf] and maxy <= self.ny1[leaf] then
    return
  end
  removeLeaf(self, leaf)
  fatten(self, leaf, minx, miny, maxx, maxy, dx, dy)
  insertLeaf(self, leaf)
  unlinkAll(self, id)
  linkAll(self, id)
end

--- Remove a proxy; its id becomes free for reuse.
---@param id integer
function Tree:remove(id)
  local leaf = checkId(self, 'remove', id)
  unlinkAll(self, id)
  removeLeaf(self, leaf)
  freeNode(self, leaf)
  self.leaf[id] = 0
  giveId(self, id)
  self.live = self.live - 1
end

--- Every pair of proxies whose exact boxes overlap (touching counts), each once.
---@param out table filled as {a1, b1, a2, b2, ...} with a < b, ascending by (a, b); entries past 2n are cleared
---@return integer n the number of pairs
function Tree:pairs(out)
  local nbr, deg, seg = self.nbr, self.deg, self.seg
  local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
  local n = 0
  for a = 1, self.idTop do
    local d = deg[a]
    if d > 0 then
      local la = nbr[a]
      local ax0, ay0, ax1, ay1 = px0[a], py0[a], px1[a], py1[a]
      local m = 0
      for k = 1, 2 * d, 2 do
        local b = la[k]
        if b > a and px0[b] <= ax1 and px1[b] >= ax0 and py0[b] <= ay1 and py1[b] >= ay0 then
          m = m + 1
          seg[m] = b
        end
      end
      if m > 0 then
        if m > 1 then sortRange(seg, m) end
        for k = 1, m do
          out[2 * n + 1], out[2 * n + 2] = a, seg[k]
          n = n + 1
        end
      end
    end
  end
  local i = 2 * n + 1
  while out[i] ~= nil do
    out[i] = nil
    i = i + 1
  end
  return n
end

--- The proxies whose exact boxes overlap the box (touching counts).
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@param out table filled with the ids, ascending; entries past k are cleared
---@return integer k the number of ids
function Tree:query(minx, miny, maxx, maxy, out)
  checkBox('query', minx, miny, maxx, maxy)
  local k = 0
  if self.root ~= 0 then
    local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
    local stack, top = self.stack, 1
    stack[1] = self.root
    while top > 0 do
      local n = stack[top]
      top = top - 1
      if x0[n] <= maxx and x1[n] >= minx and y0[n] <= maxy and y1[n] >= miny then
        local a = c1[n]
        if a == 0 then
          local id = proxyOf[n]
          if px0[id] <= maxx and px1[id] >= minx and py0[id] <= maxy and py1[id] >= miny then
            k = k + 1
            out[k] = id
          end
        else
          stack[top + 1], stack[top + 2] = a, c2[n]
          top = top + 2
        end
      end
    end
    sortRange(out, k)
  end
  local i = k + 1
  while out[i] ~= nil do
    out[i] = nil
    i = i + 1
  end
  return k
end

--- The number of proxies.
---@return integer
function Tree:count()
  return self.live
end

--- The tree's height (0 for one leaf, -1 when empty): for tests and measurements.
---@return integer
function Tree:depth()
  return self.root == 0 and -1 or self.height[self.root]
end

--- The number of candidate pairs (fat boxes overlapping): for measurements.
---@return integer
function Tree:candidates()
  local deg, s = self.deg, 0
  for id = 1, self.idTop do s = s + deg[id] end
  return s / 2
end

return Tree
