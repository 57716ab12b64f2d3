# strike: make test runs luacheck and the busted suite under every Lua VM.
VMS ?= lua5.1 lua5.2 lua5.3 lua5.4 luajit

.PHONY: test deps lint spec copy-check

test: deps lint copy-check spec

# Installs what the checks need (Debian packages) when it is missing and this machine can
# (root with apt-get); otherwise says exactly what to install.
deps:
	@bash tools/deps.sh $(VMS)

lint:
	@echo "== luacheck"
	@luacheck --formatter plain --codes .

spec:
	@bash tools/spec.sh $(VMS)

# The folder works wherever a game copies it.
copy-check:
	@bash tools/copy-check.sh $(VMS)
