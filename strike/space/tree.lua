--- The broadphase of S.pace (strike/space/Space.lua): a dynamic AABB tree. Chosen over
--- sort-and-sweep and a hierarchical grid by measurement (bench/broadphase.lua;
--- docs/space.md, "Why a tree"): it needs no cell size or bounds, its cost per frame
--- follows the moving bodies, and it answers box and ray queries in O(log n) besides the
--- pairs.
---
--- Design (ideas from Box2D's b2DynamicTree and broad phase, E. Catto, v2.4 and v3; no
--- code taken):
--- * A binary tree whose leaves hold one proxy each, stored in flat number arrays indexed
---   by node (parent, two children, height, box, proxy id) with a free list of nodes.
--- * Each leaf of a proxy that moved holds a fat box: the proxy's exact box grown by a margin
---   of MARGIN (w + h) on every side (6-22 px for 8-28 px bodies, 0.8 px for a 1 px bullet,
---   about 800 px for a 2,000 px platform, nothing for a point), then stretched ahead along the last
---   displacement by 4 times that displacement, at most 32 (w + h) per axis (so a teleport
---   does not leave a huge box behind). Margins scale with each box, so nothing depends on units
---   or on the distance from the origin. Moving a box inside its fat box costs a few
---   comparisons; leaving it reinserts the leaf and puts the proxy in the move buffer.
--- * Two trees in the same arrays: the leaves that have not moved since they were inserted
---   (walls, level geometry) under `root`, with their exact boxes, and the others under
---   `moving`, with fat boxes (as Box2D v3 keeps static and moving proxies in separate
---   trees). A leaf's first move takes it from the first to the second. (In one tree, with
---   fat boxes for all, the ancestors of a level's long walls, fattened for moves they never
---   make, were walked by every query near them, and small movers inserted under them
---   spoiled the tree as they moved: bench/movers.lua, 2,000 movers among 200 walls and
---   four border walls, 138 nodes visited per mover's query after 5 frames and 190 after 35;
---   57 and 72 with the two trees.) Queries, rays and pairs walk both.
--- * Insertion walks down choosing the child whose enlarged perimeter, plus the growth it
---   causes in every ancestor, costs least (a surface-area heuristic in 2D, after Box2D
---   v2.4's InsertLeaf). On the way back up, every node tries the four swaps of a child with
---   a grandchild on the other side and makes the one that shrinks the perimeter most (tree
---   rotations by area, as in Box2D v3, after Kopta et al., "Fast, effective BVH updates for
---   animated scenes", 2012); a node whose sides differ in height by more than 2 is first
---   rotated AVL-like (as in Box2D v2.4's Balance), which bounds the depth when area gives no
---   preference (many equal boxes).
--- * Pairs are kept, not searched for every frame (Box2D's pair set and move buffer): the
---   tree keeps the pairs whose fat boxes overlap, sorted by (a, b). `pairs` queries the
---   tree with the fat box of each proxy that moved out of its fat box (or was added) since
---   the last call, radix-sorts what it finds, merges it into the kept list (dropping the
---   old pairs of moved or removed proxies) and emits the candidates whose exact boxes
---   overlap. A frame costs O(n + candidates + moved log n); every loop is flat, with no
---   short inner loops (LuaJIT compiles them into few traces).
--- * Results are sorted (ids ascending), so they never depend on insertion history.
---
--- Ids: positive integers, stable until removed; a removed id is reused, the last freed first.
--- Boxes are closed: boxes that touch overlap. Nothing is allocated per call once the
--- arrays have grown to the world's size (n proxies, their candidates, the largest result).
local Tree = {}
Tree.__index = Tree

local min, max, huge, abs = math.min, math.max, math.huge, math.abs
local JIT = rawget(_G, 'jit') ~= nil

--- Fat margin on each side, as a fraction of the box's width + height. (Measured on 8-28 px
--- bodies moving 0.5-2 px a frame: 1/8 moves 12% of them out of their fat boxes each frame,
--- 1/4 8% (1.7 times the candidates, 40% less time on Lua 5.4), 1/2 5% (3.6 times). In
--- S.pace, the tree's work plus the rest of collisions() at N = 1,000 / 5,000, Lua 5.4, in
--- thousands of VM instructions a frame: 589 / 3,619 at 1/4, 555 / 3,322 at 0.4, 565 /
--- 3,265 at 0.6.)
local MARGIN = 0.4
--- The fat box reaches this many displacements ahead of the box...
local PREDICT = 4
--- ...but at most this many times the box's width + height, per axis (so that a teleport
--- does not leave a huge box behind, while a 1 px bullet moving 20 px a frame gets a box
--- that lasts it a few frames: at 1 it left its fat box every frame; bench/broadphase.lua's
--- mixed world at 5,000 bodies, 9.3 -> 5.0 ms a frame on LuaJIT, 23 -> 16 on Lua 5.4).
local PREDICT_LIMIT = 32
--- A node whose children's heights differ by more than this is rotated AVL-like (2 or 3
--- fight the rotations by area: as deep, and 3 to 30 times as many rotations).
local AVL_SLACK = 4
--- Sorts up to this many entries by insertion, longer ones by heapsort.
local SHORT_SORT = 12
--- A moved leaf is rotated by area this many levels above where it is inserted.
local MOVED_LEVELS = 4
-- A proxy's pending tree work: NEW and NEW_MOVED are not in the tree yet (NEW_MOVED: placed
-- since its insert, so it joins the tree of moving proxies).
local NONE, MOVED, NEW, NEW_MOVED = 0, 1, 2, 3

--- A new, empty tree.
---@return table
function Tree.new()
  return setmetatable({
    -- nodes: 0 is "none"; a leaf has child1 == 0 and height 0
    parent = {}, child1 = {}, child2 = {}, height = {}, proxyOf = {},
    -- fat boxes (unions of children for inner nodes); node 0's is infinite (see rotateArea)
    nx0 = { [0] = -huge }, ny0 = { [0] = -huge }, nx1 = { [0] = huge }, ny1 = { [0] = huge },
    -- two trees in these arrays: `root` holds the leaves that have not moved since they were
    -- inserted (exact boxes: walls, floors, level geometry), `moving` the others (fat boxes)
    root = 0, moving = 0, nodeTop = 0, freeNode = 0,
    rests = {}, nRest = 0, -- rests[id]: the proxy's leaf is under root; how many are
    nRebuilds = 0, -- bulk builds so far
    afterBulk = false, -- a bulk build since the last pairs(): see flush and pairs
    -- proxies: leaf node (0 when free), exact box, and mark[id] == frame when the proxy is
    -- in the move buffer (its kept pairs are stale)
    leaf = {}, px0 = {}, py0 = {}, px1 = {}, py1 = {}, mark = {},
    fx0 = {}, fy0 = {}, fx1 = {}, fy1 = {}, -- the fat box the leaf has or will have
    pending = {}, -- NONE, MOVED (the leaf's box is stale), NEW or NEW_MOVED (not in the tree yet)
    idTop = 0, live = 0, frame = 1,
    -- changes whenever a leaf is inserted, removed or moved in the tree: a walk of it that
    -- calls out (rayVisit's visitor) can tell the tree changed meanwhile
    version = 0,
    freeIds = {}, nFreeIds = 0, -- the free ids, a stack
    moved = {}, nMoved = 0, -- the move buffer
    stale = {}, nStale = 0, -- the proxies whose leaves await flush (pending ~= NONE)
    ca = {}, cb = {}, nCand = 0, -- kept pairs (fat boxes overlap), a < b, ascending
    da = {}, db = {}, -- the other buffer of the merge
    ka = {}, kb = {}, ta = {}, tb = {}, histogram = {}, -- new pairs, radix sort scratch
    stack = {}, -- scratch
    tstack = {}, -- scratch: rayVisit's entry distances
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

------------------------------------------------------------------ ids: the last freed first

-- (a stack: the ids of the bodies removed last are the first given again. Lowest-free-first,
-- a binary heap, cost a bullet's remove and add on Lua 5.4 about 90 of its 1,060 VM
-- instructions; a space orders its results by rank, not by id, so the policy shows nowhere.)
local function takeId(self)
  local n = self.nFreeIds
  if n == 0 then
    local id = self.idTop + 1
    self.idTop = id
    return id
  end
  self.nFreeIds = n - 1
  return self.freeIds[n]
end

local function giveId(self, id)
  local n = self.nFreeIds + 1
  self.nFreeIds = n
  self.freeIds[n] = id
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

-- Put the roots of the two trees that are not empty on the stack; returns its top.
local function seed(self, stack)
  local top, r = 0, self.root
  if r ~= 0 then
    top = 1
    stack[1] = r
  end
  r = self.moving
  if r ~= 0 then
    top = top + 1
    stack[top] = r
  end
  return top
end

-- Node `new` takes the place of `old` as the root of whichever of the two trees old is the
-- root of.
local function setRoot(self, old, new)
  if self.root == old then self.root = new else self.moving = new end
end

-- Recompute an inner node's box and height from its children.
--
-- The functions that run on every level of the tree come in two spellings: with
-- math.min/max, which LuaJIT compiles into branch-free instructions (written with `if`,
-- every comparison becomes a side exit, and the descent's combinations of them overflow
-- the trace cache and flush it), and with `if`, which the interpreters of Lua 5.1-5.4 run
-- faster than a call. Measured with bench/broadphase/measure_tree.lua.
local refit
if JIT then
  refit = function(self, n)
    local c1, c2 = self.child1, self.child2
    local x0, y0, x1, y1, h = self.nx0, self.ny0, self.nx1, self.ny1, self.height
    local a, b = c1[n], c2[n]
    x0[n], y0[n] = min(x0[a], x0[b]), min(y0[a], y0[b])
    x1[n], y1[n] = max(x1[a], x1[b]), max(y1[a], y1[b])
    h[n] = 1 + max(h[a], h[b])
  end
else
  -- (the new box and height in locals, compared with the old before they are written: true
  -- when they changed, which fixUp asks; see refitChanged)
  refit = function(self, n)
    local x0, y0, x1, y1, h = self.nx0, self.ny0, self.nx1, self.ny1, self.height
    local a, b = self.child1[n], self.child2[n]
    local nx0, ny0, nx1, ny1, nh = x0[a], y0[a], x1[a], y1[a], h[a]
    local v = x0[b]
    if v < nx0 then nx0 = v end
    v = y0[b]
    if v < ny0 then ny0 = v end
    v = x1[b]
    if v > nx1 then nx1 = v end
    v = y1[b]
    if v > ny1 then ny1 = v end
    v = h[b]
    if v > nh then nh = v end
    nh = nh + 1
    if nx0 == x0[n] and ny0 == y0[n] and nx1 == x1[n] and ny1 == y1[n] and nh == h[n] then return false end
    x0[n], y0[n], x1[n], y1[n], h[n] = nx0, ny0, nx1, ny1, nh
    return true
  end
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
    setRoot(self, a, c)
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

-- Half perimeter of the union of nodes a and b's boxes (two spellings: see refit).
local perimOf
if JIT then
  perimOf = function(self, a, b)
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    return max(x1[a], x1[b]) - min(x0[a], x0[b]) + max(y1[a], y1[b]) - min(y0[a], y0[b])
  end
else
  perimOf = function(self, a, b)
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    local ux0, uy0, ux1, uy1 = x0[a], y0[a], x1[a], y1[a]
    local vx0, vy0, vx1, vy1 = x0[b], y0[b], x1[b], y1[b]
    if vx0 < ux0 then ux0 = vx0 end
    if vy0 < uy0 then uy0 = vy0 end
    if vx1 > ux1 then ux1 = vx1 end
    if vy1 > uy1 then uy1 = vy1 end
    return ux1 - ux0 + uy1 - uy0
  end
end

-- Swap child `out` of node a (the one not holding `inner`) with grandchild `g` under
-- `inner`, then refit inner. a's box is unchanged; its height may change.
local function swap(self, a, out, inner, g)
  local parent, c1, c2 = self.parent, self.child1, self.child2
  if c1[a] == out then c1[a] = g else c2[a] = g end
  if c1[inner] == g then c1[inner] = out else c2[inner] = out end
  parent[g], parent[out] = a, inner
  refit(self, inner)
end

-- The gains of the four swaps under a node with children b, c (see rotateArea): swapping b
-- with f (c's first child, c becomes (b, g)), b with g, c with d (b's first child), c with e.
local function gains(self, b, c)
  local c1, c2, x0, y0, x1, y1 = self.child1, self.child2, self.nx0, self.ny0, self.nx1, self.ny1
  local d, e, f, g = c1[b], c2[b], c1[c], c2[c]
  local pb, pc = x1[b] - x0[b] + y1[b] - y0[b], x1[c] - x0[c] + y1[c] - y0[c]
  return pc - perimOf(self, b, g), pc - perimOf(self, b, f), pb - perimOf(self, c, e), pb - perimOf(self, c, d)
end

-- Which swap gains most, 1 to 4 in the order of gains(), when one gains at all.
local function whichSwap(self, b, c)
  local gainF, gainG, gainD, gainE = gains(self, b, c)
  local best = max(gainF, gainG, gainD, gainE)
  if best == gainF then return 1 end
  if best == gainG then return 2 end
  if best == gainD then return 3 end
  return 4
end

-- 0 when no swap under a node with children b, c gains, else which one does (whichSwap).
-- The usual answer, 0, takes no branch on LuaJIT; the other path computes the gains again
-- rather than keep them live across the branch: a trace exit with a dozen numbers live in
-- registers made LuaJIT abort every side trace there ("register coalescing too complex":
-- hundreds of aborted traces a second in a moving world, and flushes of the trace cache).
local function bestSwap(self, b, c)
  local gainF, gainG, gainD, gainE = gains(self, b, c)
  if max(gainF, gainG, gainD, gainE) <= 0 then return 0 end
  return whichSwap(self, b, c)
end

-- Tree rotation by surface area (Box2D v3's tree rotations, after Kopta et al., "Fast,
-- effective BVH updates for animated scenes", 2012): of the four swaps of a child of n
-- with a grandchild on the other side, make the one that shrinks the changed child's
-- perimeter most, if any does (then returns true). n's own box is unchanged. A leaf's
-- "children" are node 0, whose box is infinite: swaps with them never gain.
local function rotateArea(self, n)
  local c1, c2 = self.child1, self.child2
  local b, c = c1[n], c2[n]
  local k = bestSwap(self, b, c)
  if k == 0 then return false end
  if k == 1 then
    swap(self, n, b, c, c1[c])
  elseif k == 2 then
    swap(self, n, b, c, c2[c])
  elseif k == 3 then
    swap(self, n, c, b, c1[b])
  else
    swap(self, n, c, b, c2[b])
  end
  return true
end

-- Refit node n; true when its box or height changed. (Its own function: the old box is
-- dead once it returns, so the trace exits of the rotations that follow carry fewer live
-- values; see bestSwap.) The interpreters' refit already answers that.
local refitChanged = refit
if JIT then
  refitChanged = function(self, n)
    local x0, y0, x1, y1, h = self.nx0, self.ny0, self.nx1, self.ny1, self.height
    local ox0, oy0, ox1, oy1, oh = x0[n], y0[n], x1[n], y1[n], h[n]
    refit(self, n)
    return x0[n] ~= ox0 or y0[n] ~= oy0 or x1[n] ~= ox1 or y1[n] ~= oy1 or h[n] ~= oh
  end
end

-- Refit and rebalance the nodes from n up: AVL-like when one side is much taller, then, on
-- the first `levels` nodes, by area. Stops at the first node that comes out as it was (box,
-- height, children), since nothing above it changes then.
local function fixUp(self, n, levels)
  local parent, c1, c2, h = self.parent, self.child1, self.child2, self.height
  while n ~= 0 do
    levels = levels - 1
    local a, b = c1[n], c2[n]
    local d = h[b] - h[a]
    local same = true
    if d > AVL_SLACK then
      n, same = rotateUp(self, n, b), false
    elseif d < -AVL_SLACK then
      n, same = rotateUp(self, n, a), false
    end
    if refitChanged(self, n) then same = false end
    if levels >= 0 and rotateArea(self, n) then
      refit(self, n) -- (the height may change)
      same = false
    end
    if same then return end
    n = parent[n]
  end
end


-- The sibling for a new leaf: descend to the node whose pairing costs least, where the cost
-- of stopping at node n is twice the half perimeter of n + leaf (the new parent and the
-- enlarged ancestors), and going down to child c adds the growth of c (its enlarged half
-- perimeter, less its own if c is an inner node whose cost is already counted) to the
-- growth n passes on to its ancestors.
-- (Two spellings: see refit.)
local findSibling
if JIT then
  findSibling = function(self, leaf, n)
    local c1, c2, h = self.child1, self.child2, self.height
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    local lx0, ly0, lx1, ly1 = x0[leaf], y0[leaf], x1[leaf], y1[leaf]
    while c1[n] ~= 0 do -- (min(height, 1): 0 for a leaf, 1 for an inner node, no branch)
      local a, b = c1[n], c2[n]
      local combined = max(x1[n], lx1) - min(x0[n], lx0) + max(y1[n], ly1) - min(y0[n], ly0)
      local cost = 2 * combined
      local inherit = 2 * (combined - (x1[n] - x0[n] + y1[n] - y0[n]))
      local costA = max(x1[a], lx1) - min(x0[a], lx0) + max(y1[a], ly1) - min(y0[a], ly0) + inherit
        - min(h[a], 1) * (x1[a] - x0[a] + y1[a] - y0[a])
      local costB = max(x1[b], lx1) - min(x0[b], lx0) + max(y1[b], ly1) - min(y0[b], ly0) + inherit
        - min(h[b], 1) * (x1[b] - x0[b] + y1[b] - y0[b])
      if cost < costA and cost < costB then break end
      if costB < costA then n = b else n = a end
    end
    return n
  end
else
  findSibling = function(self, leaf, n)
    local c1, c2 = self.child1, self.child2
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    local lx0, ly0, lx1, ly1 = x0[leaf], y0[leaf], x1[leaf], y1[leaf]
    while c1[n] ~= 0 do -- (written out: no calls, for the interpreters)
      local a, b = c1[n], c2[n]
      local ux0, uy0, ux1, uy1 = x0[n], y0[n], x1[n], y1[n]
      local area = ux1 - ux0 + uy1 - uy0
      if lx0 < ux0 then ux0 = lx0 end
      if ly0 < uy0 then uy0 = ly0 end
      if lx1 > ux1 then ux1 = lx1 end
      if ly1 > uy1 then uy1 = ly1 end
      local combined = ux1 - ux0 + uy1 - uy0
      local cost, inherit = 2 * combined, 2 * (combined - area)
      ux0, uy0, ux1, uy1 = x0[a], y0[a], x1[a], y1[a]
      local costA = inherit
      if c1[a] ~= 0 then costA = costA - (ux1 - ux0 + uy1 - uy0) end
      if lx0 < ux0 then ux0 = lx0 end
      if ly0 < uy0 then uy0 = ly0 end
      if lx1 > ux1 then ux1 = lx1 end
      if ly1 > uy1 then uy1 = ly1 end
      costA = costA + (ux1 - ux0 + uy1 - uy0)
      ux0, uy0, ux1, uy1 = x0[b], y0[b], x1[b], y1[b]
      local costB = inherit
      if c1[b] ~= 0 then costB = costB - (ux1 - ux0 + uy1 - uy0) end
      if lx0 < ux0 then ux0 = lx0 end
      if ly0 < uy0 then uy0 = ly0 end
      if lx1 > ux1 then ux1 = lx1 end
      if ly1 > uy1 then uy1 = ly1 end
      costB = costB + (ux1 - ux0 + uy1 - uy0)
      if cost < costA and cost < costB then break end
      if costB < costA then n = b else n = a end
    end
    return n
  end
end

-- Put leaf into the tree of resting leaves, or with `moving` into the other, beside the
-- sibling findSibling chooses, rotating by area on the first `levels` levels above it (see
-- fixUp).
local function insertLeaf(self, leaf, levels, moving)
  local root = moving and self.moving or self.root
  if root == 0 then
    if moving then self.moving = leaf else self.root = leaf end
    self.parent[leaf] = 0
    return
  end
  local parent, c1, c2 = self.parent, self.child1, self.child2
  local n = findSibling(self, leaf, root)
  local old = parent[n]
  local p = newNode(self)
  parent[p], c1[p], c2[p] = old, n, leaf
  parent[n], parent[leaf] = p, p
  if old == 0 then
    setRoot(self, n, p)
  elseif c1[old] == n then
    c1[old] = p
  else
    c2[old] = p
  end
  fixUp(self, p, levels)
end

local function removeLeaf(self, leaf)
  if self.parent[leaf] == 0 then -- (the root of its tree)
    setRoot(self, leaf, 0)
    return
  end
  local parent, c1, c2 = self.parent, self.child1, self.child2
  local p = parent[leaf]
  local g = parent[p]
  local sibling = c1[p] == leaf and c2[p] or c1[p]
  if g == 0 then
    setRoot(self, p, sibling)
    freeNode(self, p)
    parent[sibling] = 0
    return
  end
  freeNode(self, p)
  parent[sibling] = g
  if c1[g] == p then c1[g] = sibling else c2[g] = sibling end
  fixUp(self, g, 0)
end

------------------------------------------------------------------ pairs

-- Query the tree with the fat box of moved proxy i and append the pairs it finds to ka, kb
-- (smaller id first) from position k + 1; returns the new end. A pair of two moved proxies
-- is added by the query of the smaller one only.
local function findPairs(self, i, k)
  local leaf, mark, frame = self.leaf[i], self.mark, self.frame
  local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local ka, kb = self.ka, self.kb
  local qx0, qy0, qx1, qy1 = x0[leaf], y0[leaf], x1[leaf], y1[leaf]
  local stack = self.stack
  local top = seed(self, stack)
  while top > 0 do
    local n = stack[top]
    top = top - 1
    if x0[n] <= qx1 and x1[n] >= qx0 and y0[n] <= qy1 and y1[n] >= qy0 then
      local a = c1[n]
      if a ~= 0 then
        stack[top + 1], stack[top + 2] = a, c2[n]
        top = top + 2
      else
        local j = proxyOf[n]
        if j > i then
          k = k + 1
          ka[k], kb[k] = i, j
        elseif j < i and mark[j] ~= frame then
          k = k + 1
          ka[k], kb[k] = j, i
        end
      end
    end
  end
  return k
end

-- Put proxy id in the move buffer (once per frame): its kept pairs are stale.
local function pushMoved(self, id)
  local mark, frame = self.mark, self.frame
  if mark[id] ~= frame then
    mark[id] = frame
    local n = self.nMoved + 1
    self.nMoved = n
    self.moved[n] = id
  end
end

-- Bring the tree up to date with the moves and inserts in the move buffer (Box2D v3 also
-- defers its tree work to the step: the updates run in one loop, not in the caller's).
-- The work waits in a list of its own (`stale`: each proxy once per wait, whatever its
-- place in the move buffer), so that the queries between two calls of pairs, which flush
-- first, do not walk the whole move buffer each time.
------------------------------------------------------------------ bulk build

-- Partition leaves[lo..hi] so that leaves[mid] holds the leaf of rank mid along `keys`
-- (keys[i] is twice the centre of leaves[i] along the split axis, `other` along the other
-- one; both move with their leaf), those before it keys no larger and those after no smaller
-- (Hoare's selection, the middle entry as pivot: deterministic).
local function selectRank(leaves, keys, other, lo, hi, mid)
  while lo < hi do
    local pivot = keys[(lo + hi - (lo + hi) % 2) / 2]
    local i, j = lo, hi
    while i <= j do
      while keys[i] < pivot do i = i + 1 end
      while keys[j] > pivot do j = j - 1 end
      if i <= j then
        keys[i], keys[j] = keys[j], keys[i]
        other[i], other[j] = other[j], other[i]
        leaves[i], leaves[j] = leaves[j], leaves[i]
        i, j = i + 1, j - 1
      end
    end
    if mid <= j then hi = j elseif mid >= i then lo = i else return end
  end
end

-- A subtree over leaves[lo..hi] (their boxes set; cx, cy twice their centres, in the same
-- order), split top-down at the median centre along the longer side of the centres'
-- bounds; returns its root, parent unset. (The centres sit beside the leaves, read in order
-- and moved with them, instead of read through the leaves from the node arrays at every
-- level: the same tree, its bulk build of 20,000 boxes 77-79 -> 70-74 ms on Lua 5.4 and
-- 16-18 -> 15-16.5 on LuaJIT, three alternating runs. A tree of leaves paired in Morton
-- order built in 10-11 ms and 25-37, but queries on it took 1.4-1.7 times as long.)
local function buildRange(self, leaves, cx, cy, lo, hi)
  if lo == hi then return leaves[lo] end
  local cx0, cy0, cx1, cy1 = huge, huge, -huge, -huge
  for i = lo, hi do
    local x, y = cx[i], cy[i]
    if x < cx0 then cx0 = x end
    if x > cx1 then cx1 = x end
    if y < cy0 then cy0 = y end
    if y > cy1 then cy1 = y end
  end
  local mid = (lo + hi - (lo + hi) % 2) / 2
  if cx1 - cx0 >= cy1 - cy0 then
    selectRank(leaves, cx, cy, lo, hi, mid)
  else
    selectRank(leaves, cy, cx, lo, hi, mid)
  end
  local a = buildRange(self, leaves, cx, cy, lo, mid)
  local b = buildRange(self, leaves, cx, cy, mid + 1, hi)
  local p = newNode(self)
  self.child1[p], self.child2[p] = a, b
  self.parent[a], self.parent[b] = p, p
  refit(self, p)
  return p
end

-- Many proxies inserted at once (a level loading: at least BULK, and at least half as many as
-- the tree of resting leaves held): that tree is built again from its leaves and the new
-- ones, top-down (as Box2D v3 rebuilds a tree in bulk; a median
-- split here), instead of inserting the new leaves one by one: 20,000 boxes added, the first
-- query 95 -> 10 ms on LuaJIT and 295 -> 40 ms on Lua 5.4. Their pending work is done.
local BULK = 256
local function bulkBuild(self, nNew)
  -- (its scratch is its own: kept, two arrays as long as the tree cost 26 bytes a body on
  -- LuaJIT and 52 on Lua 5.4 at 20,000 bodies, for a build that comes once a level)
  local leaves = {}
  local c1, c2 = self.child1, self.child2
  local k = 0
  -- (the old tree: its leaves kept, its inner nodes freed)
  local stack = self.stack
  local top = 0
  if self.root ~= 0 then
    top = 1
    stack[1] = self.root
  end
  while top > 0 do
    local n = stack[top]
    top = top - 1
    local a = c1[n]
    if a == 0 then
      k = k + 1
      leaves[k] = n
    else
      stack[top + 1], stack[top + 2] = a, c2[n]
      top = top + 2
      freeNode(self, n)
    end
  end
  local stale, pending, leafOf = self.stale, self.pending, self.leaf
  local fx0, fy0, fx1, fy1 = self.fx0, self.fy0, self.fx1, self.fy1
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  for m = 1, self.nStale do
    local id = stale[m]
    if pending[id] == NEW then
      local leaf = leafOf[id]
      x0[leaf], y0[leaf], x1[leaf], y1[leaf] = fx0[id], fy0[id], fx1[id], fy1[id]
      k = k + 1
      leaves[k] = leaf
      pending[id] = NONE
      self.rests[id] = true
    end
  end
  self.nRest = k
  self.nRebuilds = self.nRebuilds + 1
  local cx, cy = {}, {}
  for i = 1, k do
    local l = leaves[i]
    cx[i], cy[i] = x0[l] + x1[l], y0[l] + y1[l]
  end
  local root = buildRange(self, leaves, cx, cy, 1, k)
  self.parent[root] = 0
  self.root = root
  self.afterBulk = true -- (flush and pairs let go of their lists, as long as the level: see there)
  return nNew
end

local function flush(self)
  local n = self.nStale
  if n == 0 then return end
  self.version = self.version + 1
  local stale, pending, leafOf = self.stale, self.pending, self.leaf
  if n >= BULK then
    local nNew = 0
    for m = 1, n do
      if pending[stale[m]] == NEW then nNew = nNew + 1 end
    end
    if nNew >= BULK and nNew + nNew >= self.nRest then bulkBuild(self, nNew) end
  end
  local fx0, fy0, fx1, fy1 = self.fx0, self.fy0, self.fx1, self.fy1
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local rests = self.rests
  self.nStale = 0
  for m = 1, n do
    local id = stale[m]
    local state = pending[id]
    if state ~= NONE then
      local leaf = leafOf[id]
      if state == MOVED then
        removeLeaf(self, leaf)
        if rests[id] then
          rests[id] = false
          self.nRest = self.nRest - 1
        end
      end
      x0[leaf], y0[leaf], x1[leaf], y1[leaf] = fx0[id], fy0[id], fx1[id], fy1[id]
      -- (a new leaf rotates by area all the way up, a moved one only near where it lands:
      -- 1,000 circles moving for 3,000 frames, Lua 5.4, counted in VM instructions: the
      -- tree's work per frame 468k all the way up, 394k at 4 levels, 359k at 2; the sum of
      -- the inner nodes' perimeters after it 196k, 201k and 225k)
      insertLeaf(self, leaf, state == MOVED and MOVED_LEVELS or huge, state ~= NEW)
      if state == NEW then
        rests[id] = true
        self.nRest = self.nRest + 1
      end
      pending[id] = NONE
    end
  end
  if self.afterBulk then self.stale = {} end -- (a list as long as the level, not needed again soon)
end

-- Stable counting sort of the k pairs (sa, sb) by sa (the key array given first) into
-- (da, db); ids are 1 .. top.
local function countingSort(count, top, key, other, k, dkey, dother)
  for id = 1, top do count[id] = 0 end
  for i = 1, k do
    local v = key[i]
    count[v] = count[v] + 1
  end
  local at = 1
  for id = 1, top do
    local c = count[id]
    count[id] = at
    at = at + c
  end
  for i = 1, k do
    local v = key[i]
    local p = count[v]
    count[v] = p + 1
    dkey[p], dother[p] = v, other[i]
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

-- Give proxy id the fat box of its exact box moved by (dx, dy) since last time: grown by the
-- margin on every side, and by the predicted move (PREDICT times the last one, at most
-- PREDICT_LIMIT of the box's size each way) on the side it moves to. Two spellings, as
-- refit's above.
local fatten
if JIT then
  fatten = function(self, id, minx, miny, maxx, maxy, dx, dy)
    local s = (maxx - minx) + (maxy - miny)
    local m = s * MARGIN
    local x0, y0, x1, y1 = minx - m, miny - m, maxx + m, maxy + m
    local limit = s * PREDICT_LIMIT
    -- (no branches: LuaJIT compiles min and max to single instructions, and a branch here,
    -- in the loop that places every moved body, made side traces it could not compile,
    -- "register coalescing too complex", hundreds of times a second at N = 5,000)
    dx, dy = min(max(dx * PREDICT, -limit), limit), min(max(dy * PREDICT, -limit), limit)
    self.fx0[id], self.fy0[id] = x0 + min(dx, 0), y0 + min(dy, 0)
    self.fx1[id], self.fy1[id] = x1 + max(dx, 0), y1 + max(dy, 0)
  end
else
  fatten = function(self, id, minx, miny, maxx, maxy, dx, dy)
    local s = (maxx - minx) + (maxy - miny)
    local m = s * MARGIN
    local x0, y0, x1, y1 = minx - m, miny - m, maxx + m, maxy + m
    local limit = s * PREDICT_LIMIT
    dx, dy = dx * PREDICT, dy * PREDICT
    if dx > limit then dx = limit elseif dx < -limit then dx = -limit end
    if dy > limit then dy = limit elseif dy < -limit then dy = -limit end
    if dx < 0 then x0 = x0 + dx else x1 = x1 + dx end
    if dy < 0 then y0 = y0 + dy else y1 = y1 + dy end
    self.fx0[id], self.fy0[id], self.fx1[id], self.fy1[id] = x0, y0, x1, y1
  end
end

--- Add a proxy for the box (closed: a box of zero size is a point or a segment).
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@return integer id positive, stable until removed; the last freed id is reused first
function Tree:insert(minx, miny, maxx, maxy)
  checkBox('insert', minx, miny, maxx, maxy)
  local id = takeId(self)
  self.px0[id], self.py0[id], self.px1[id], self.py1[id] = minx, miny, maxx, maxy
  local leaf = newNode(self)
  self.leaf[id], self.proxyOf[leaf] = leaf, id
  self.fx0[id], self.fy0[id], self.fx1[id], self.fy1[id] = minx, miny, maxx, maxy
  self.pending[id] = NEW
  local k = self.nStale + 1
  self.nStale, self.stale[k] = k, id
  pushMoved(self, id)
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
  checkId(self, 'update', id)
  checkBox('update', minx, miny, maxx, maxy)
  self:place(id, minx, miny, maxx, maxy)
end

--- Tree:update without its checks, for a caller whose ids and boxes are known good (S.pace:
--- strike's bounds are finite and ordered).
---@param id integer
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
function Tree:place(id, minx, miny, maxx, maxy)
  local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
  local dx = (minx + maxx - px0[id] - px1[id]) * 0.5
  local dy = (miny + maxy - py0[id] - py1[id]) * 0.5
  px0[id], py0[id], px1[id], py1[id] = minx, miny, maxx, maxy
  if minx >= self.fx0[id] and miny >= self.fy0[id] and maxx <= self.fx1[id] and maxy <= self.fy1[id] then
    return
  end
  fatten(self, id, minx, miny, maxx, maxy, dx, dy)
  local pending = self.pending
  local state = pending[id]
  if state == NONE then
    pending[id] = MOVED
    local k = self.nStale + 1
    self.nStale, self.stale[k] = k, id
  elseif state == NEW then
    pending[id] = NEW_MOVED
  end
  pushMoved(self, id)
end

--- Remove a proxy; its id becomes free for reuse.
---@param id integer
function Tree:remove(id)
  local leaf = checkId(self, 'remove', id)
  pushMoved(self, id) -- (its kept pairs become stale)
  self.version = self.version + 1
  if self.pending[id] < NEW then removeLeaf(self, leaf) end
  if self.rests[id] then
    self.rests[id] = false
    self.nRest = self.nRest - 1
  end
  self.pending[id] = NONE
  freeNode(self, leaf)
  self.leaf[id] = 0
  giveId(self, id)
  self.live = self.live - 1
end

--- Every pair of proxies whose exact boxes overlap (touching counts), each once.
---@param out table filled as {a1, b1, a2, b2, ...} with a < b, ascending by (a, b); entries past 2n are cleared
---@return integer n the number of pairs
function Tree:pairs(out)
  local ca, cb, nCand = self.ca, self.cb, self.nCand
  local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
  local nMoved = self.nMoved
  if nMoved > 0 then
    -- the pairs of the moved proxies, sorted by (a, b): radix sort, b then a
    flush(self)
    local moved, leaf, k = self.moved, self.leaf, 0
    for m = 1, nMoved do
      local i = moved[m]
      if leaf[i] ~= 0 then k = findPairs(self, i, k) end -- (removed since: skipped)
    end
    local ka, kb, ta, tb, top = self.ka, self.kb, self.ta, self.tb, self.idTop
    countingSort(self.histogram, top, kb, ka, k, tb, ta)
    countingSort(self.histogram, top, ta, tb, k, ka, kb)
    -- merge them with the kept pairs of proxies that did not move, into (da, db)
    local da, db, mark, frame = self.da, self.db, self.mark, self.frame
    local i, j, d = 1, 1, 0
    while true do -- (one flat loop)
      if i <= nCand then
        local a, b = ca[i], cb[i]
        if mark[a] == frame or mark[b] == frame then -- stale: dropped
          i = i + 1
        elseif j <= k and (ka[j] < a or (ka[j] == a and kb[j] < b)) then
          d = d + 1
          da[d], db[d] = ka[j], kb[j]
          j = j + 1
        else
          d = d + 1
          da[d], db[d] = a, b
          i = i + 1
        end
      elseif j <= k then
        d = d + 1
        da[d], db[d] = ka[j], kb[j]
        j = j + 1
      else
        break
      end
    end
    self.ca, self.cb, self.da, self.db = da, db, ca, cb
    ca, cb, nCand = da, db, d
    self.nCand, self.nMoved, self.frame = d, 0, frame + 1
    if self.afterBulk then -- (the move buffer held every new body of the level)
      self.moved, self.afterBulk = {}, false
    end
  end
  local n = 0
  for c = 1, nCand do
    local a, b = ca[c], cb[c]
    if px0[b] <= px1[a] and px1[b] >= px0[a] and py0[b] <= py1[a] and py1[b] >= py0[a] then
      out[2 * n + 1], out[2 * n + 2] = a, b
      n = n + 1
    end
  end
  local i = 2 * n + 1
  while out[i] ~= nil do
    out[i] = nil
    i = i + 1
  end
  return n
end

-- The ids of the leaves whose exact boxes meet the box, into out[1..k], unsorted; returns k.
-- (Two spellings, see refit: LuaJIT's tests a node when it pops it, one data-dependent branch
-- a node, which keeps its traces few; the interpreters' tests a node before pushing it, so
-- that the stack holds only nodes that meet the box: 8 % fewer VM instructions a move for
-- bench/movers.lua's 2,000 movers on Lua 5.4; on LuaJIT it made a third more traces of the
-- tree, 303-305 against 218-258 in three runs each, for about the same machine code.)
local boxWalk
if JIT then
  boxWalk = function(self, minx, miny, maxx, maxy, out)
    local k = 0
    local stack = self.stack
    local top = seed(self, stack)
    local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
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
    return k
  end
else
  boxWalk = function(self, minx, miny, maxx, maxy, out)
    local k = 0
    local stack = self.stack
    local top = seed(self, stack)
    local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
    local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
    local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
    local s = 0
    for i = 1, top do -- (the roots)
      local n = stack[i]
      if x0[n] <= maxx and x1[n] >= minx and y0[n] <= maxy and y1[n] >= miny then
        s = s + 1
        stack[s] = n
      end
    end
    top = s
    while top > 0 do
      local n = stack[top]
      top = top - 1
      local a = c1[n]
      if a == 0 then
        local id = proxyOf[n]
        if px0[id] <= maxx and px1[id] >= minx and py0[id] <= maxy and py1[id] >= miny then
          k = k + 1
          out[k] = id
        end
      else
        if x0[a] <= maxx and x1[a] >= minx and y0[a] <= maxy and y1[a] >= miny then
          top = top + 1
          stack[top] = a
        end
        a = c2[n]
        if x0[a] <= maxx and x1[a] >= minx and y0[a] <= maxy and y1[a] >= miny then
          top = top + 1
          stack[top] = a
        end
      end
    end
    return k
  end
end

--- The proxies whose exact boxes overlap the box (touching counts).
--- (Moves since the last pairs or query reach the tree first.)
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@param out table filled with the ids, ascending; entries past k are cleared
---@return integer k the number of ids
function Tree:query(minx, miny, maxx, maxy, out)
  checkBox('query', minx, miny, maxx, maxy)
  flush(self)
  local k = boxWalk(self, minx, miny, maxx, maxy, out)
  if k > 0 then sortRange(out, k) end
  local i = k + 1
  while out[i] ~= nil do
    out[i] = nil
    i = i + 1
  end
  return k
end

-- Where the ray (x, y) + t (dx, dy), 1 / dx = ix, 1 / dy = iy, enters the box grown by e,
-- if it does so within [0, maxT]; else -1. The slab test (Kay and Kajiya, 1986), without
-- branches but for a direction parallel to an axis (zx, zy: its x or y component is 0, or
-- so small that its inverse is infinite), which LuaJIT compiles into one guard per ray:
-- with the branches, its side traces failed ("register coalescing too complex").
-- (two spellings, as refit's: min and max for LuaJIT, comparisons for the interpreters,
-- where math.min and math.max are calls)
local entry
if JIT then
  entry = function(bx0, by0, bx1, by1, e, x, y, zx, zy, ix, iy, maxT)
    bx0, by0, bx1, by1 = bx0 - e, by0 - e, bx1 + e, by1 + e
    local lo, hi = 0, maxT
    if zx then
      if x < bx0 or x > bx1 then return -1 end
    else
      local t1, t2 = (bx0 - x) * ix, (bx1 - x) * ix
      lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    end
    if zy then
      if y < by0 or y > by1 then return -1 end
    else
      local t1, t2 = (by0 - y) * iy, (by1 - y) * iy
      lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    end
    if lo <= hi then return lo end
    return -1
  end
else
  entry = function(bx0, by0, bx1, by1, e, x, y, zx, zy, ix, iy, maxT)
    bx0, by0, bx1, by1 = bx0 - e, by0 - e, bx1 + e, by1 + e
    local lo, hi = 0, maxT
    if zx then
      if x < bx0 or x > bx1 then return -1 end
    else
      local t1, t2 = (bx0 - x) * ix, (bx1 - x) * ix
      if t1 > t2 then t1, t2 = t2, t1 end
      if t1 > lo then lo = t1 end
      if t2 < hi then hi = t2 end
    end
    if zy then
      if y < by0 or y > by1 then return -1 end
    else
      local t1, t2 = (by0 - y) * iy, (by1 - y) * iy
      if t1 > t2 then t1, t2 = t2, t1 end
      if t1 > lo then lo = t1 end
      if t2 < hi then hi = t2 end
    end
    if lo <= hi then return lo end
    return -1
  end
end

-- The constants of a walk along the ray from (x, y) along (dx, dy): the inverse direction,
-- whether each component is as good as 0 (its inverse is infinite), and the pad every box
-- is grown by: a rounding's worth, relative to the coordinates and the origin's (a point's
-- or an edge's box has no width, and the slab arithmetic's rounding alone could miss it, or
-- put a box's entry past a hit exactly on its side). One pad for the whole walk, from the
-- root's box, which holds every box below it: at least each box's own.
local function rayWalk(self, x, y, dx, dy)
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local m = 0
  for r = 1, 2 do
    local root = r == 1 and self.root or self.moving
    if root ~= 0 then
      m = max(m, 2 * max(abs(x0[root]), abs(x1[root])) + 2 * max(abs(y0[root]), abs(y1[root])))
    end
  end
  local ix, iy = 1 / dx, 1 / dy
  local e = 1e-12 * (m + abs(x) + abs(y))
  return ix, iy, ix == huge or ix == -huge, iy == huge or iy == -huge, e
end

--- The proxies whose exact boxes the ray from (x, y) along (dx, dy) reaches within
--- [0, maxT]: their ids into `ids` and where the ray enters each box into `ts` (0 when it
--- starts inside), in no particular order; returns their number. The slab test (Kay and
--- Kajiya, 1986), a zero direction component tested on its own (0 * inf is NaN). For
--- every body a ray crosses (S.pace's rayCastAll); a closest hit is rayVisit's.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxT number
---@param ids integer[]
---@param ts number[]
---@return integer
function Tree:rayCandidates(x, y, dx, dy, maxT, ids, ts)
  flush(self)
  local stack, k = self.stack, 0
  local top = seed(self, stack)
  if top == 0 then return 0 end
  local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
  local ix, iy, zx, zy, e = rayWalk(self, x, y, dx, dy)
  while top > 0 do
    local n = stack[top]
    top = top - 1
    local a = c1[n]
    local t -- (a leaf's exact box, an inner node's union of fat boxes)
    if a == 0 then
      local id = proxyOf[n]
      t = entry(px0[id], py0[id], px1[id], py1[id], e, x, y, zx, zy, ix, iy, maxT)
    else
      t = entry(x0[n], y0[n], x1[n], y1[n], e, x, y, zx, zy, ix, iy, maxT)
    end
    if t >= 0 then
      if a == 0 then
        k = k + 1
        ids[k], ts[k] = proxyOf[n], t
      else
        stack[top + 1], stack[top + 2] = a, c2[n]
        top = top + 2
      end
    end
  end
  return k
end

--- The proxies whose exact boxes the ray reaches, nearer boxes first, for a closest hit:
--- `visit(ctx, id, t, maxT)` is called with each proxy whose box the ray enters at t <=
--- maxT, and returns the new maxT (the distance of the best hit so far, or maxT as it
--- was); boxes entered beyond it are not visited, nor is what is below them. The walk
--- descends into the nearer child first. Every proxy whose box the ray enters within the
--- final maxT is visited (what the caller's ties need); others may be too. Boxes are grown
--- as rayCandidates grows them.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxT number
---@param visit fun(ctx: any, id: integer, t: number, maxT: number): number
---@param ctx any
---@param stack table|nil the walk's scratch, nodes (default: the tree's); a visitor that walks the
---tree again (a filter querying the space) must be given its own
---@param tstack table|nil the walk's scratch, entry distances (the same)
function Tree:rayVisit(x, y, dx, dy, maxT, visit, ctx, stack, tstack)
  flush(self)
  if self.root == 0 and self.moving == 0 then return end
  local c1, c2, proxyOf = self.child1, self.child2, self.proxyOf
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local px0, py0, px1, py1 = self.px0, self.py0, self.px1, self.py1
  local ix, iy, zx, zy, e = rayWalk(self, x, y, dx, dy)
  local ts, top = tstack or self.tstack, 0
  stack = stack or self.stack
  -- (the two roots, the nearer popped first; an empty tree's root, node 0, is not entered)
  do
    local ra, rb = self.root, self.moving
    local ta = ra == 0 and -1 or entry(x0[ra], y0[ra], x1[ra], y1[ra], e, x, y, zx, zy, ix, iy, maxT)
    local tb = rb == 0 and -1 or entry(x0[rb], y0[rb], x1[rb], y1[rb], e, x, y, zx, zy, ix, iy, maxT)
    if ta > tb then ra, rb, ta, tb = rb, ra, tb, ta end
    if tb >= 0 then
      top = top + 1
      stack[top], ts[top] = rb, tb
    end
    if ta >= 0 then
      top = top + 1
      stack[top], ts[top] = ra, ta
    end
  end
  while top > 0 do
    local n, tn = stack[top], ts[top]
    top = top - 1
    if tn <= maxT then
      local a = c1[n]
      if a == 0 then
        maxT = visit(ctx, proxyOf[n], tn, maxT)
      else
        local b = c2[n]
        local ta, tb -- (as rayCandidates: a leaf's exact box, an inner node's union)
        if c1[a] == 0 then
          local id = proxyOf[a]
          ta = entry(px0[id], py0[id], px1[id], py1[id], e, x, y, zx, zy, ix, iy, maxT)
        else
          ta = entry(x0[a], y0[a], x1[a], y1[a], e, x, y, zx, zy, ix, iy, maxT)
        end
        if c1[b] == 0 then
          local id = proxyOf[b]
          tb = entry(px0[id], py0[id], px1[id], py1[id], e, x, y, zx, zy, ix, iy, maxT)
        else
          tb = entry(x0[b], y0[b], x1[b], y1[b], e, x, y, zx, zy, ix, iy, maxT)
        end
        if ta > tb then a, b, ta, tb = b, a, tb, ta end -- (a: the nearer, popped first)
        if tb >= 0 then
          top = top + 1
          stack[top], ts[top] = b, tb
        end
        if ta >= 0 then
          top = top + 1
          stack[top], ts[top] = a, ta
        end
      end
    end
  end
end

--- Visit every node: calls fn(ctx, minx, miny, maxx, maxy, depth, isLeaf, moving) for each
--- (fat boxes of leaves; unions of inner nodes), for drawing and tests: the tree of the
--- proxies that have not moved since they were inserted first (moving false), then the
--- other (moving true), each from its root at depth 0.
---@param fn fun(ctx, minx, miny, maxx, maxy, depth, leaf, moving)
---@param ctx any
function Tree:eachNode(fn, ctx)
  flush(self)
  local c1, c2 = self.child1, self.child2
  local x0, y0, x1, y1 = self.nx0, self.ny0, self.nx1, self.ny1
  local depths = self.depths
  if not depths then
    depths = {}
    self.depths = depths
  end
  local stack = self.stack
  for r = 1, 2 do
    local moving = r == 2
    local top = 1
    stack[1], depths[1] = moving and self.moving or self.root, 0
    if stack[1] == 0 then top = 0 end
    while top > 0 do
      local n, d = stack[top], depths[top]
      top = top - 1
      local a = c1[n]
      fn(ctx, x0[n], y0[n], x1[n], y1[n], d, a == 0, moving)
      if a ~= 0 then
        stack[top + 1], depths[top + 1] = a, d + 1
        stack[top + 2], depths[top + 2] = c2[n], d + 1
        top = top + 2
      end
    end
  end
end

--- The exact box of proxy id.
---@param id integer
---@return number minx, number miny, number maxx, number maxy
function Tree:box(id)
  return self.px0[id], self.py0[id], self.px1[id], self.py1[id]
end

--- The number of proxies.
---@return integer
function Tree:count()
  return self.live
end

--- The height of the taller of the two trees (0 for one leaf, -1 when both are empty): for
--- tests and measurements.
---@return integer
function Tree:depth()
  flush(self)
  local a, b = self.root, self.moving
  return max(a == 0 and -1 or self.height[a], b == 0 and -1 or self.height[b])
end

--- How many times the tree of resting proxies was built again in bulk: for tests and
--- measurements.
---@return integer
function Tree:rebuilds()
  return self.nRebuilds
end

--- The number of candidate pairs (fat boxes overlapping) at the last call of pairs: for
--- measurements.
---@return integer
function Tree:candidates()
  return self.nCand
end

return Tree
