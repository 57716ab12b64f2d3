-- Every relative link of the README and the guides (docs/, examples/) resolves: the file or
-- folder it names exists, and its #anchor is a heading of that file (or of the same file),
-- as GitHub names headings (spec/helpers/markdown.lua, slug). Links to web addresses are
-- not fetched.
local md = require('spec.helpers.markdown')

local function exists(path)
  return os.rename(path, path) ~= nil
end

-- `path` relative to the folder of `file`, with `.` and `..` resolved.
local function resolve(file, path)
  local parts = {}
  for p in (file:match('^(.*)/') or '.'):gmatch('[^/]+') do parts[#parts + 1] = p end
  for p in path:gmatch('[^/]+') do
    if p == '..' then
      if #parts == 0 or parts[#parts] == '..' then parts[#parts + 1] = '..' else parts[#parts] = nil end
    elseif p ~= '.' then
      parts[#parts + 1] = p
    end
  end
  local out = {}
  for _, p in ipairs(parts) do
    if p ~= '.' then out[#out + 1] = p end
  end
  return #out > 0 and table.concat(out, '/') or '.'
end

local anchorsOf = {}
local function anchors(path)
  if not anchorsOf[path] then anchorsOf[path] = (md.anchors(md.read(path))) end
  return anchorsOf[path]
end

-- What is wrong with a link of `file` to `target`, or nil.
local function broken(file, target)
  if target:match('^%a[%w+.-]*:') then return nil end -- https:, mailto:
  if target == '' then return 'an empty link' end
  if target:sub(1, 1) == '/' then return 'an absolute path: ' .. target end
  local path, anchor = target:match('^([^#]*)#(.*)$')
  if not path then path = target end
  local dest = path == '' and file or resolve(file, path)
  if not exists(dest) then return ('%s: no such file or folder (%s)'):format(target, dest) end
  if anchor then
    if not dest:match('%.md$') then return ('%s: an anchor in a file that is not markdown'):format(target) end
    if not anchors(dest)[anchor] then return ('%s: %s has no heading #%s'):format(target, dest, anchor) end
  end
  return nil
end

describe('the links of the documentation', function()
  local files = md.files()
  local total = 0
  for _, file in ipairs(files) do
    it(file .. ': every relative link and #anchor resolves', function()
      local bad = {}
      local links = md.links(md.read(file))
      total = total + #links
      for _, l in ipairs(links) do
        local why = broken(file, l.target)
        if why then bad[#bad + 1] = ('%s:%d: %s'):format(file, l.line, why) end
      end
      assert.are.same({}, bad)
    end)
  end

  it('are found (the README links to every guide)', function()
    assert.is_true(total >= 50, ('%d links'):format(total))
    local readme = md.read('README.md')
    for _, f in ipairs(files) do
      if f:match('^docs/') then
        assert.is_truthy(readme:find('](' .. f .. ')', 1, true) or readme:find('](' .. f .. '#', 1, true),
          'README.md does not link to ' .. f)
      end
    end
  end)
end)

describe('the link check', function()
  it('names headings as GitHub does', function()
    assert.equals('the-space-space', md.slug('The space: `S.pace`'))
    assert.equals('drawing-with-löve', md.slug('Drawing with LÖVE'))
    assert.equals('many-movers-side-by-side', md.slug('Many movers, side by side'))
    assert.equals('s_weep-and-s_ite', md.slug('S_weep and S_ite'))
    assert.equals('a--b', md.slug('a — b'))
    assert.equals('links-kept', md.slug('[links](x.md) kept'))
    local set, list = md.anchors('# A\n```\n# not a heading\n```\n## A\n### A\n')
    assert.same({ 'a', 'a-1', 'a-2' }, list)
    assert.is_nil(set['not-a-heading'])
  end)

  it('resolves paths against the linking file\'s folder', function()
    assert.equals('README.md', resolve('docs/space.md', '../README.md'))
    assert.equals('docs/rays.md', resolve('docs/space.md', 'rays.md'))
    assert.equals('docs/demo.png', resolve('README.md', 'docs/demo.png'))
    assert.equals('examples/tiled', resolve('docs/tiled.md', '../examples/tiled/'))
  end)

  it('finds a missing file, a missing heading, and leaves web addresses alone', function()
    assert.is_nil(broken('README.md', 'https://example.org/x#y'))
    assert.is_nil(broken('README.md', 'docs/demo.png'))
    assert.matches('no such file', broken('README.md', 'docs/nothing.md'))
    assert.matches('has no heading #no%-such%-heading', broken('README.md', '#no-such-heading'))
    assert.matches('absolute path', broken('README.md', '/etc/passwd'))
  end)
end)
