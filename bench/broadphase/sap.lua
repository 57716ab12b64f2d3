--- Broadphase candidate 3 for S.pace: sort and sweep on x (D. Baraff's "sweep and prune",
--- 1992, as the order kept by insertion sort from frame to frame: moving bodies barely change
--- it, so the sort is nearly linear). Exact boxes, no tuning, any coordinates. Pairs: sweep
--- the sorted minima, test y for every box whose x interval starts inside the current one's.
--- A box that spans much of the world in x (a long platform) meets many in the sweep: this
--- candidate's weak case, which the mixed world measures.
local Sap = {}
Sap.__index = Sap

--- A new empty broadphase.
---@return table
function Sap.new()
  return setmetatable({ x0 = {}, y0 = {}, x1 = {}, y1 = {}, order = {}, n = 0, live = {}, free = {}, nfree = 0,
    count_ = 0, keys = {} }, Sap)
end

--- Insert a box; returns its id (the most recently freed id first, else a new one).
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@return integer id
function Sap:insert(minx, miny, maxx, maxy)
  local id
  if self.nfree > 0 then
    id = self.free[self.nfree]
    self.free[self.nfree] = nil
    self.nfree = self.nfree - 1
  else
    id = self.count_ + self.nfree + 1
    while self.live[id] ~= nil do id = id + 1 end
  end
  self.x0[id], self.y0[id], self.x1[id], self.y1[id] = minx, miny, maxx, maxy
  self.live[id] = true
  self.n = self.n + 1
  self.order[self.n] = id
  self.count_ = self.count_ + 1
  return id
end

--- New bounds for box `id`.
---@param id integer
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
function Sap:update(id, minx, miny, maxx, maxy)
  self.x0[id], self.y0[id], self.x1[id], self.y1[id] = minx, miny, maxx, maxy
end

--- Remove box `id`.
---@param id integer
function Sap:remove(id)
  self.live[id] = false
  self.nfree = self.nfree + 1
  self.free[self.nfree] = id
  self.count_ = self.count_ - 1
  local order, n = self.order, self.n
  local j = 0
  for i = 1, n do
    local o = order[i]
    if o ~= id then j = j + 1; order[j] = o end
  end
  for i = n, j + 1, -1 do order[i] = nil end
  self.n = j
end

--- The number of boxes.
---@return integer
function Sap:count() return self.count_ end

--- Every pair of overlapping boxes (closed intervals) as a flat list {a1, b1, ...}, a < b,
--- ascending; returns the count.
---@param out integer[]
---@return integer
function Sap:pairs(out)
  local order, n, x0, y0, x1, y1 = self.order, self.n, self.x0, self.y0, self.x1, self.y1
  for i = 2, n do -- insertion sort on the minima (nearly sorted from the last frame)
    local id = order[i]
    local v = x0[id]
    local j = i - 1
    while j >= 1 and x0[order[j]] > v do
      order[j + 1] = order[j]
      j = j - 1
    end
    order[j + 1] = id
  end
  local keys, k = self.keys, 0
  for p = 1, n do
    local a = order[p]
    local ax1, ay0, ay1 = x1[a], y0[a], y1[a]
    for q = p + 1, n do
      local b = order[q]
      if x0[b] > ax1 then break end
      if y0[b] <= ay1 and y1[b] >= ay0 then
        k = k + 1
        keys[k] = a < b and a * 67108864 + b or b * 67108864 + a
      end
    end
  end
  for i = #keys, k + 1, -1 do keys[i] = nil end
  table.sort(keys)
  for i = 1, k do
    local key = keys[i]
    local a = (key - key % 67108864) / 67108864
    out[2 * i - 1], out[2 * i] = a, key - a * 67108864
  end
  for i = #out, 2 * k + 1, -1 do out[i] = nil end
  return k
end

--- The boxes overlapping the box given, ascending, into `out`; returns the count.
---@param minx number
---@param miny number
---@param maxx number
---@param maxy number
---@param out integer[]
---@return integer
function Sap:query(minx, miny, maxx, maxy, out)
  local order, n, x0, y0, x1, y1 = self.order, self.n, self.x0, self.y0, self.x1, self.y1
  local k = 0
  for p = 1, n do
    local id = order[p]
    if x0[id] <= maxx and x1[id] >= minx and y0[id] <= maxy and y1[id] >= miny then
      k = k + 1
      out[k] = id
    end
  end
  for i = #out, k + 1, -1 do out[i] = nil end
  table.sort(out)
  return k
end

return Sap
