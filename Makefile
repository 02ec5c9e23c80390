# vroc: hand-written Makefile.
#
#   make            build ./vroc
#   make check      build and run every test, normal build and ASan+UBSan build
#   make bench      build and run the benchmarks
#   make demo       the main job: run a thesis scene and write its stereo frames
#   make deps       install the missing Debian packages (apt-get, sudo when not root)
#   make install    binary, man page and scenes under $(DESTDIR)$(PREFIX)
#   make clean      remove what make built
#
# Objects go to build/ (normal) and build-san/ (sanitizers); headers are tracked
# with -MMD.

PREFIX  ?= /usr/local
DESTDIR ?=
BINDIR   = $(PREFIX)/bin
MANDIR   = $(PREFIX)/share/man/man1
SCENEDIR = $(PREFIX)/share/vroc/scenes

VERSION  = 0.1.0
PKGS     = readline osmesa libpng qhull_r sndfile
CC      ?= cc
WARN     = -Wall -Wextra -Wpedantic -Werror
CSTD     = -std=c17 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
# no code reads errno after sqrt, sin and the like: they compile to the bare
# instruction, with no call kept for setting errno (about 2% of the simulation's
# instructions, 6% of its code)
MATH     = -fno-math-errno
OPT     ?= -O2 -g
PKG_CFLAGS := $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS   := $(shell pkg-config --libs $(PKGS) 2>/dev/null)
CFLAGS_ALL = $(CSTD) $(MATH) $(WARN) $(OPT) $(PKG_CFLAGS) -Isrc -Ibuild/gen \
             -DVROC_VERSION='"$(VERSION)"' -DVROC_SCENEDIR='"$(SCENEDIR)"' $(CFLAGS)
LIBS       = $(PKG_LIBS) -lm
TEST_LIBS  = $(shell pkg-config --libs cmocka 2>/dev/null)
SAN        = -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all

# The core and shell: every src/*.c but main.c goes into a library the tests link.
SRC      = $(filter-out src/main.c,$(wildcard src/*.c))
COMMANDS = $(sort $(wildcard commands/*))
TESTS    = $(patsubst tests/%.c,%,$(wildcard tests/test_*.c))
BENCHES  = $(patsubst bench/%.c,%,$(wildcard bench/bench_*.c))

OBJ      = $(patsubst src/%.c,build/%.o,$(SRC)) build/help_data.o
SAN_OBJ  = $(patsubst src/%.c,build-san/%.o,$(SRC)) build-san/help_data.o

.PHONY: all check check-normal check-san bench demo deps install uninstall clean man
.DELETE_ON_ERROR:

all: vroc man/vroc.1

# every object is rebuilt when the compiler or its flags change: build/flags
# holds them, rewritten (and so newer) only when they differ
FLAGS_NOW := $(CC) $(CFLAGS_ALL) | $(OPT) | $(SAN)
ifneq ($(file < build/flags),$(FLAGS_NOW))
$(shell mkdir -p build)
$(file > build/flags,$(FLAGS_NOW))
endif

# main.o holds the scenes folder: it is rebuilt when PREFIX changes
build/prefix: FORCE
	@mkdir -p build
	@echo '$(SCENEDIR)' | cmp -s - $@ || echo '$(SCENEDIR)' > $@
build/main.o build-san/main.o: build/prefix
.PHONY: FORCE
FORCE:

vroc: build/main.o build/libvroc.a
	$(CC) $(OPT) -o $@ $^ $(LIBS) $(LDFLAGS)

build/libvroc.a: $(OBJ)
	ar rcs $@ $^

build/%.o: src/%.c build/flags | build/gen/help_data.c
	@mkdir -p build
	$(CC) $(CFLAGS_ALL) -MMD -MP -c -o $@ $<

build/help_data.o: build/gen/help_data.c build/flags
	$(CC) $(CFLAGS_ALL) -c -o $@ $<

build/gen/help_data.c: $(COMMANDS) src/mkhelp.awk
	@mkdir -p build/gen
	awk -f src/mkhelp.awk -v mode=c $(COMMANDS) > $@

# The man page's command reference is built from commands/ like help is.
man/vroc.1: man/vroc.1.in $(COMMANDS) src/mkhelp.awk
	awk -f src/mkhelp.awk -v mode=man -v template=man/vroc.1.in $(COMMANDS) > $@

# ---- sanitizer build ----
build-san/%.o: src/%.c build/flags | build/gen/help_data.c
	@mkdir -p build-san
	$(CC) $(CFLAGS_ALL) $(SAN) -MMD -MP -c -o $@ $<

build-san/help_data.o: build/gen/help_data.c build/flags
	@mkdir -p build-san
	$(CC) $(CFLAGS_ALL) $(SAN) -c -o $@ $<

build-san/libvroc.a: $(SAN_OBJ)
	ar rcs $@ $^

build-san/vroc: build-san/main.o build-san/libvroc.a
	$(CC) $(OPT) $(SAN) -o $@ $^ $(LIBS)

# ---- tests ----
build/tests/%: tests/%.c tests/check.h tests/worlds.h build/libvroc.a build/flags
	@mkdir -p build/tests
	$(CC) $(CFLAGS_ALL) -MMD -MP -o $@ $< build/libvroc.a $(LIBS) $(TEST_LIBS)

build-san/tests/%: tests/%.c tests/check.h tests/worlds.h build-san/libvroc.a build/flags
	@mkdir -p build-san/tests
	$(CC) $(CFLAGS_ALL) $(SAN) -o $@ $< build-san/libvroc.a $(LIBS) $(TEST_LIBS)

check: deps
	@$(MAKE) --no-print-directory check-build
	@sh tests/run.sh

check-build: vroc man/vroc.1 build-san/vroc $(addprefix build/tests/,$(TESTS)) \
             $(addprefix build-san/tests/,$(TESTS))

# ---- benchmarks ----
build/bench/%: bench/%.c bench/bench.h build/libvroc.a build/flags
	@mkdir -p build/bench
	$(CC) $(CFLAGS_ALL) -O2 -o $@ $< build/libvroc.a $(LIBS)

bench: deps
	@$(MAKE) --no-print-directory vroc $(addprefix build/bench/,$(BENCHES))
	@sh bench/run.sh

# ---- the main job ----
demo: deps
	@$(MAKE) --no-print-directory vroc
	./vroc -b scenes/simple.vroc -c 'output = "frames"; record = on; run 30; stats'
	@echo "demo: stereo frames of the Simple scene are in frames/"

deps:
	@sh src/deps.sh

install: vroc man/vroc.1
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(MANDIR) $(DESTDIR)$(SCENEDIR)
	install -m 755 vroc $(DESTDIR)$(BINDIR)/vroc
	install -m 644 man/vroc.1 $(DESTDIR)$(MANDIR)/vroc.1
	install -m 644 scenes/*.vroc $(DESTDIR)$(SCENEDIR)/

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/vroc $(DESTDIR)$(MANDIR)/vroc.1
	rm -rf $(DESTDIR)$(PREFIX)/share/vroc

clean:
	rm -rf build build-san vroc tests/out

-include $(wildcard build/*.d build-san/*.d build/tests/*.d)
