# strike: make test runs luacheck and the busted suite under every Lua VM.
VMS ?= lua5.1 lua5.2 lua5.3 lua5.4 luajit

.PHONY: test deps lint spec

test: deps lint spec

# Installs what the checks need (Debian packages) when it is missing and this machine can
# (root with apt-get); otherwise says exactly what to install.
deps:
	@bash tools/deps.sh $(VMS)

lint:
	@echo "== luacheck"
	@luacheck --formatter plain --codes .

spec:
	@bash tools/spec.sh $(VMS)
