-- Lets `require 'strike'` work from the repository root on Lua 5.1 and LuaJIT, whose
-- default package.path has no "./?/init.lua". The library itself is the strike/ folder.
return require('strike.init')
