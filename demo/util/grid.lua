--- A uniform grid for the broad phase of the stress scene: every body is listed in each
--- cell its bounding box touches, and only bodies sharing a cell are paired. Pure Lua, and
--- nothing allocated per frame once the cells exist.
---
--- A pair of bodies can share several cells; it is reported once, from its *reference
--- cell*: the cell holding the minimum corner of the intersection of their two boxes,
--- (max(minx1, minx2), max(miny1, miny2)). When the boxes overlap that corner lies in both,
--- so both were listed in that cell; when they do not, the pair may be skipped everywhere,
--- which is right, since then they cannot collide.
local Grid = {}
Grid.__index = Grid

local floor = math.floor

--- A grid of `size`-pixel square cells over a w x h area (bodies outside it are clamped to
--- the border cells).
---@param size number @param w number @param h number
function Grid.new(size, w, h)
  return setmetatable({
    size = size, cols = math.ceil(w / size), rows = math.ceil(h / size),
    cells = {}, used = {}, nused = 0,
    minx = {}, miny = {}, -- each id's box corner, for the reference-cell test
  }, Grid)
end

-- The column or row of coordinate v, clamped to [0, n - 1].
local function slot(v, size, n)
  local i = floor(v / size)
  if i < 0 then return 0 elseif i >= n then return n - 1 end
  return i
end

--- Forget every body (the cells' tables are kept for the next frame).
function Grid:clear()
  local cells = self.cells
  for i = 1, self.nused do
    cells[self.used[i]].n = 0
    self.used[i] = nil
  end
  self.nused = 0
end

--- List body `id` in every cell that its box (minx, miny)-(maxx, maxy) touches.
function Grid:insert(id, minx, miny, maxx, maxy)
  local size, cols, rows, cells = self.size, self.cols, self.rows, self.cells
  self.minx[id], self.miny[id] = minx, miny
  for row = slot(miny, size, rows), slot(maxy, size, rows) do
    for col = slot(minx, size, cols), slot(maxx, size, cols) do
      local key = row * cols + col
      local cell = cells[key]
      if not cell then
        cell = { n = 0 }
        cells[key] = cell
      end
      if cell.n == 0 then
        self.nused = self.nused + 1
        self.used[self.nused] = key
      end
      cell.n = cell.n + 1
      cell[cell.n] = id
    end
  end
end

--- Call fn(i, j, ...) once for every pair of bodies that share a cell (see the top of
--- this file for how each pair is reported once). Returns the number of pairs reported.
---@param fn function
---@return integer
function Grid:eachPair(fn, ...)
  local size, cols, rows, cells = self.size, self.cols, self.rows, self.cells
  local minx, miny = self.minx, self.miny
  local count = 0
  for u = 1, self.nused do
    local key = self.used[u]
    local cell = cells[key]
    for a = 1, cell.n - 1 do
      local i = cell[a]
      for b = a + 1, cell.n do
        local j = cell[b]
        local rx = minx[i] > minx[j] and minx[i] or minx[j]
        local ry = miny[i] > miny[j] and miny[i] or miny[j]
        if slot(ry, size, rows) * cols + slot(rx, size, cols) == key then
          count = count + 1
          fn(i, j, ...)
        end
      end
    end
  end
  return count
end

return Grid
