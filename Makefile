# The two commands a fresh machine needs (README.md). Everything else is CMake.
.PHONY: demo test
demo:
	bash scripts/demo.sh
test:
	bash scripts/test.sh
