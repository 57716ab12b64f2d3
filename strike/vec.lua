--- Scalar 2D math: vectors travel as pairs of numbers, never as tables.
local vec = {}

--- (x, y) turned by the angle whose cosine and sine are c and s (positive turns +x toward
--- +y). Pass c * k and s * k to turn and scale by k in one step.
---@param x number
---@param y number
---@param c number
---@param s number
---@return number x
---@return number y
function vec.rotate(x, y, c, s)
  return c * x - s * y, s * x + c * y
end

return vec
