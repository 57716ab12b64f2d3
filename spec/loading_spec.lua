-- Loading: plain require, from any folder name, no globals, no printing, no shelling out,
-- no directory listing, with or without LÖVE.
local function unloadStrike()
  for name in pairs(package.loaded) do
    if name == 'strike' or name:match('^strike%.') or name:match('^libs%.strike') then
      package.loaded[name] = nil
    end
  end
end

local searchers = package.searchers or package.loaders -- luacheck: ignore 143

-- A searcher that serves `libs.strike[.x.y]` from the strike/ folder, the way a copy of the
-- folder under libs/ would be found.
local function libsSearcher(name)
  local rest = name:match('^libs%.strike(.*)$')
  if not rest then return nil end
  local path = 'strike' .. (rest == '' and '/init' or rest:gsub('%.', '/')) .. '.lua'
  local chunk, err = loadfile(path)
  if not chunk then return '\n\tno file ' .. path .. ' (' .. tostring(err) .. ')' end
  return chunk, path
end

describe('require', function()
  local saved = {}
  before_each(function()
    saved.print, saved.popen, saved.execute = print, io.popen, os.execute
    unloadStrike()
  end)
  after_each(function()
    print, io.popen, os.execute = saved.print, saved.popen, saved.execute -- luacheck: ignore 121 122
    rawset(_G, 'love', nil)
    unloadStrike()
    package.loaded.strike = nil
  end)

  it('defines no globals, prints nothing, runs no shell command and lists no folder', function()
    local function forbid(what) return function() error('strike must not call ' .. what, 2) end end
    print, io.popen, os.execute = forbid('print'), forbid('io.popen'), forbid('os.execute') -- luacheck: ignore 121 122
    rawset(_G, 'love', { filesystem = { getDirectoryItems = forbid('love.filesystem.getDirectoryItems') } })
    local before = {}
    for k in pairs(_G) do before[k] = true end
    local S = require('strike')
    local shape = S.hapes.Rectangle(0, 0, 1)
    assert.is_nil(S.hapes.NotAShape)
    assert.is_nil(S.trikers.NotACollider)
    assert.is_table(S.AT(shape, shape))
    for k in pairs(_G) do assert(before[k], 'strike defined the global ' .. tostring(k)) end
    for k in pairs(before) do assert(rawget(_G, k) ~= nil, 'strike removed the global ' .. tostring(k)) end
  end)

  it('works from a folder with any name, requiring its parts relatively', function()
    table.insert(searchers, 2, libsSearcher)
    finally(function()
      for i = #searchers, 1, -1 do
        if searchers[i] == libsSearcher then table.remove(searchers, i) end
      end
    end)
    local S = require('libs.strike')
    for name in pairs(package.loaded) do
      assert(not name:match('^strike'), 'a copy under libs/ loaded ' .. name)
    end
    local m = S.triking(S.trikers.Circle(0, 0, 2), S.trikers.Circle(3, 0, 2))
    assert.equals(1, m.depth)
    assert.is_table(package.loaded['libs.strike.shapes.Circle'])
    local S2 = require('libs.strike.init') -- the path for Lua 5.1 without ?/init.lua
    assert.is_function(S2.AT)
  end)

  it('is the same library through the repository-root shim and strike.init', function()
    local S = require('strike')
    assert.equals(S, require('strike.init'))
    assert.is_string(S._VERSION)
  end)
end)

describe('the source', function()
  -- Every module strike loads, as file paths.
  local function sources()
    unloadStrike()
    require('strike')
    local files = {}
    for name in pairs(package.loaded) do
      if name:match('^strike%.') and name ~= 'strike.init' then
        files[#files + 1] = name:gsub('%.', '/') .. '.lua'
      end
    end
    files[#files + 1] = 'strike/init.lua'
    table.sort(files)
    return files
  end

  local function read(path)
    local f = assert(io.open(path, 'r'))
    local text = f:read('*a')
    f:close()
    return text
  end

  it('uses none of the names that differ between Lua versions, outside compat.lua', function()
    local banned = { 'setfenv', 'getfenv', 'math%.atan2', 'table%.unpack', 'loadstring', 'math%.pow', 'goto ',
      'bit32', '//', 'table%.pack', 'love%.', 'io%.', 'os%.', 'print%(' }
    local files = sources()
    assert.is_true(#files >= 20)
    for _, path in ipairs(files) do
      if path ~= 'strike/compat.lua' then
        local n = 0
        for line in (read(path) .. '\n'):gmatch('([^\n]*)\n') do
          n = n + 1
          local code = line:gsub('%-%-.*$', '')
          for _, pat in ipairs(banned) do
            assert(not code:find(pat), ('%s:%d uses %s: %s'):format(path, n, pat, line))
          end
        end
      end
    end
  end)

end)
