--- Assertions shared by the specs.
local expect = {}

--- `fn` must be a one-line function making one bad call: it must raise an error whose
--- message starts with "<this spec file>:<that line>: " (the caller's line) and contains
--- `text` (plain).
---@param fn function @param text string
function expect.raisesAt(fn, text)
  local info = debug.getinfo(fn, 'S')
  local ok, err = pcall(fn)
  assert(not ok, 'expected an error containing: ' .. text)
  err = tostring(err)
  local prefix = info.short_src .. ':' .. info.linedefined .. ': '
  assert(err:sub(1, #prefix) == prefix,
    ('expected the error at the caller\'s line "%s", got "%s"'):format(prefix, err))
  assert(err:find(text, 1, true), ('expected the error to contain "%s", got "%s"'):format(text, err))
end

--- |a - b| <= tol (default 1e-9), with a readable message.
function expect.near(a, b, tol, what)
  tol = tol or 1e-9
  assert(type(a) == 'number' and math.abs(a - b) <= tol,
    ('%sexpected %.17g within %g of %.17g'):format(what and (what .. ': ') or '', a, tol, b))
end

--- Compare two flat lists of numbers element-wise.
function expect.nearList(got, want, tol)
  assert(#got == #want, ('expected %d values, got %d'):format(#want, #got))
  for i = 1, #want do expect.near(got[i], want[i], tol, 'value ' .. i) end
end

return expect
