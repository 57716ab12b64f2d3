--- A small seeded PRNG for property specs: the same sequence on every VM.
-- Park–Miller "minimal standard" generator (Park & Miller, CACM 1988) with
-- Schrage's factorisation, so every intermediate stays below 2^31 and is
-- exact in a double: identical on Lua 5.1, 5.2, 5.3, 5.4 and LuaJIT.
local PRNG = {}
PRNG.__index = PRNG

local M, A, Q, R = 2147483647, 16807, 127773, 2836

--- @param seed integer any integer; 0 is mapped to 1
--- @return table
function PRNG.new(seed)
  seed = math.floor(seed or 1) % M
  if seed == 0 then seed = 1 end
  return setmetatable({ seed = seed, state = seed }, PRNG)
end

--- @return number uniform in (0, 1)
function PRNG:next()
  local s = self.state
  local hi = math.floor(s / Q)
  local lo = s - hi * Q
  s = A * lo - R * hi
  if s <= 0 then s = s + M end
  self.state = s
  return s / M
end

--- @param a number
--- @param b number
--- @return number uniform in (a, b)
function PRNG:range(a, b)
  return a + (b - a) * self:next()
end

--- @param a integer
--- @param b integer
--- @return integer uniform in [a, b]
function PRNG:int(a, b)
  local v = a + math.floor((b - a + 1) * self:next())
  if v > b then v = b end
  return v
end

--- The seed to start from: STRIKE_SEED from the environment, else a fixed default.
--- @param default integer
--- @return integer
function PRNG.seedFromEnv(default)
  local s = tonumber(os.getenv('STRIKE_SEED') or '')
  return s and math.floor(s) or default
end

return PRNG
