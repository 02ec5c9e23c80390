# vroc: hand-written Makefile.
#
#   make               build ./vroc
#   make check         build and run every test: normal, ASan+UBSan and validation builds
#   make check-long    the long sweeps (tests/long/): every scene saved every 10th
#                      frame to 300, and 50 random worlds, continued to the bit
#   make bench         build and run the benchmarks
#   make demo          the main job: run a thesis scene and write its stereo frames,
#                      and a movie of them with the collisions' sound
#   make deps          install the missing Debian packages (apt-get, sudo when not root)
#   make record-hashes record the scenes' trace hashes anew (after an intended change)
#   make fuzz          AFL++ campaigns of FUZZ_TIME seconds each, of the language and
#                      of the four mesh readers (FUZZ_TARGETS; tools/fuzz.sh)
#   make install       binary, man page and scenes under $(DESTDIR)$(PREFIX)
#   make clean         remove what make built
#
# The layers are libraries, each linked only with what it may use:
#   build/libvroc-core.a   src/core/: the simulation (libc, libm and qhull only; its
#                          objects see no header outside src/core/)
#   build/libvroc-mesh.a   src/mesh/: the mesh file readers (libc and the core only)
#   build/libvroc.a        src/shell/ (but main.c), src/view/, src/sound/ and src/hand/, on top of
#                          the core and the readers
# The core's unit tests link the core library alone, and the readers' tests and
# fuzz targets the readers and the core, so a call from a layer into a higher one
# fails to link.  Objects go to build/ (normal), build-san/
# (sanitizers) and build-val/ (validation: the schedule's and the polyhedra's
# invariants checked after every internal step); headers are tracked with -MMD.

PREFIX  ?= /usr/local
DESTDIR ?=
BINDIR   = $(PREFIX)/bin
MANDIR   = $(PREFIX)/share/man/man1
SCENEDIR = $(PREFIX)/share/vroc/scenes

VERSION  = 0.1.0
CORE_PKGS = qhull_r
PKGS     = readline osmesa libpng qhull_r sndfile samplerate libpulse-simple libpulse nettle sdl2
# linked: all but OSMesa, which the views load with dlopen when they first draw
# (src/view/gl_load.h), so that a run that draws nothing never maps it, and SDL2,
# loaded the same way when the live window first opens (src/view/window.h);
# nettle gives the SHA-256 that save writes of a polyhedron's file
LINK_PKGS = readline libpng qhull_r sndfile samplerate libpulse-simple libpulse nettle
CC      ?= cc
WARN     = -Wall -Wextra -Wpedantic -Werror -Wshadow -Wmissing-prototypes
CSTD     = -std=c17 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
# no code reads errno after sqrt, sin and the like: they compile to the bare
# instruction, with no call kept for setting errno (about 2% of the simulation's
# instructions, 6% of its code)
MATH     = -fno-math-errno
OPT     ?= -O2 -g
CORE_CFLAGS := $(shell pkg-config --cflags $(CORE_PKGS) 2>/dev/null)
CORE_LIBS   := $(shell pkg-config --libs $(CORE_PKGS) 2>/dev/null) -lm
PKG_CFLAGS  := $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS    := $(shell pkg-config --libs $(LINK_PKGS) 2>/dev/null)
BASE       = $(CSTD) $(MATH) $(WARN) $(OPT) $(CFLAGS)
# the core: no include path into the project (its headers sit beside its sources)
CFLAGS_CORE = $(BASE) $(CORE_CFLAGS)
# the readers: "core/shape.h", and no package's headers
CFLAGS_MESH = $(BASE) -Isrc
# the shell, the views, the tests and the benchmarks: "core/world.h", "view/view.h"
CFLAGS_ALL = $(BASE) $(PKG_CFLAGS) -Isrc -Ibuild/gen \
             -DVROC_VERSION='"$(VERSION)"' -DVROC_SCENEDIR='"$(SCENEDIR)"'
LIBS       = $(PKG_LIBS) -lm
TEST_LIBS  = $(shell pkg-config --libs cmocka 2>/dev/null)
SAN        = -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
VAL        = -DVROC_VALIDATE

CORE_SRC  = $(sort $(wildcard src/core/*.c))
MESH_SRC  = $(sort $(wildcard src/mesh/*.c))
UPPER_SRC = $(sort $(filter-out src/shell/main.c,$(wildcard src/shell/*.c)) $(wildcard src/view/*.c) \
                   $(wildcard src/sound/*.c) $(wildcard src/hand/*.c))
COMMANDS  = $(sort $(wildcard commands/*))
# the core's own tests link libvroc-core.a alone; the others the whole program
CORE_TESTS  = test_broad test_closest test_collide test_contact test_flight test_friction test_geometry test_instant test_lasting test_lcp test_physics test_schedule test_spin
# the readers' tests link the readers and the core
MESH_TESTS  = test_mesh
UPPER_TESTS = $(filter-out $(CORE_TESTS) $(MESH_TESTS),$(patsubst tests/%.c,%,$(wildcard tests/test_*.c)))
BENCHES  = $(patsubst bench/%.c,%,$(wildcard bench/bench_*.c))
# the Bullet peer of the gas benchmark (bench/bullet_gas.cpp), built when Debian's
# libbullet-dev is there (make deps installs it)
BULLET  := $(shell pkg-config --exists bullet 2>/dev/null && echo build/bench/bullet_gas)
CXX     ?= c++

# objects of build dir $(1)
core_obj  = $(patsubst src/%.c,$(1)/%.o,$(CORE_SRC))
mesh_obj  = $(patsubst src/%.c,$(1)/%.o,$(MESH_SRC))
upper_obj = $(patsubst src/%.c,$(1)/%.o,$(UPPER_SRC)) $(1)/help_data.o

.PHONY: all check check-long check-build bench demo deps install uninstall clean record-hashes fuzz
.DELETE_ON_ERROR:

all: vroc man/vroc.1

# every object is rebuilt when the compiler or its flags change: build/flags
# holds them, rewritten (and so newer) only when they differ
FLAGS_NOW := $(CC) $(CFLAGS_ALL) | $(CFLAGS_CORE) | $(SAN) | $(VAL)
ifneq ($(file < build/flags),$(FLAGS_NOW))
$(shell mkdir -p build)
$(file > build/flags,$(FLAGS_NOW))
endif

# main.o holds the scenes folder: it is rebuilt when PREFIX changes
build/prefix: FORCE
	@mkdir -p build
	@echo '$(SCENEDIR)' | cmp -s - $@ || echo '$(SCENEDIR)' > $@
build/shell/main.o build-san/shell/main.o build-val/shell/main.o: build/prefix
.PHONY: FORCE
FORCE:

build/gen/help_data.c: $(COMMANDS) tools/mkhelp.awk
	@mkdir -p build/gen
	awk -f tools/mkhelp.awk -v mode=c $(COMMANDS) > $@

# The man page's command reference is built from commands/ like help is.
man/vroc.1: man/vroc.1.in $(COMMANDS) tools/mkhelp.awk
	awk -f tools/mkhelp.awk -v mode=man -v template=man/vroc.1.in $(COMMANDS) > $@

# ---- the builds: $(1) the folder, $(2) its extra flags, $(3) its compiler
# when not $(CC) ----
define BUILD
$(1)/core/%.o: src/core/%.c build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_CORE) $(2) -MMD -MP -c -o $$@ $$<

$(1)/shell/%.o: src/shell/%.c build/flags | build/gen/help_data.c
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_ALL) $(2) -MMD -MP -c -o $$@ $$<

$(1)/mesh/%.o: src/mesh/%.c build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_MESH) $(2) -MMD -MP -c -o $$@ $$<

$(1)/view/%.o: src/view/%.c build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_ALL) $(2) -MMD -MP -c -o $$@ $$<

$(1)/sound/%.o: src/sound/%.c build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_ALL) $(2) -MMD -MP -c -o $$@ $$<

$(1)/hand/%.o: src/hand/%.c build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_ALL) $(2) -MMD -MP -c -o $$@ $$<

$(1)/help_data.o: build/gen/help_data.c build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_ALL) $(2) -c -o $$@ $$<

$(1)/libvroc-core.a: $(call core_obj,$(1))
	rm -f $$@
	ar rcs $$@ $$^

$(1)/libvroc-mesh.a: $(call mesh_obj,$(1))
	rm -f $$@
	ar rcs $$@ $$^

$(1)/libvroc.a: $(call upper_obj,$(1))
	rm -f $$@
	ar rcs $$@ $$^

$(1)/vroc: $(1)/shell/main.o $(1)/libvroc.a $(1)/libvroc-mesh.a $(1)/libvroc-core.a
	$$(or $(3),$$(CC)) $$(OPT) $(2) -o $$@ $$^ $$(LIBS) $$(LDFLAGS)

# the readers' fuzz target (tools/fuzz.sh): one file, read as the format named
$(1)/tests/fuzz_mesh: tests/fuzz_mesh.c $(1)/libvroc-mesh.a $(1)/libvroc-core.a build/flags
	@mkdir -p $$(@D)
	$$(or $(3),$$(CC)) $$(CFLAGS_MESH) $(2) -o $$@ $$< $(1)/libvroc-mesh.a $(1)/libvroc-core.a $$(CORE_LIBS)

$(addprefix $(1)/tests/,$(CORE_TESTS)): $(1)/tests/%: tests/%.c tests/check.h tests/worlds.h $(1)/libvroc-core.a build/flags
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_ALL) $(2) -MMD -MP -o $$@ $$< $(1)/libvroc-core.a $$(CORE_LIBS) $$(TEST_LIBS)

$(addprefix $(1)/tests/,$(MESH_TESTS)): $(1)/tests/%: tests/%.c tests/check.h tests/worlds.h $(1)/libvroc-mesh.a $(1)/libvroc-core.a build/flags
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_MESH) $(2) -MMD -MP -o $$@ $$< $(1)/libvroc-mesh.a $(1)/libvroc-core.a $$(CORE_LIBS) $$(TEST_LIBS)

$(addprefix $(1)/tests/,$(UPPER_TESTS)): $(1)/tests/%: tests/%.c tests/check.h tests/worlds.h $(1)/libvroc.a $(1)/libvroc-mesh.a $(1)/libvroc-core.a build/flags
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_ALL) $(2) -MMD -MP -o $$@ $$< $(1)/libvroc.a $(1)/libvroc-mesh.a $(1)/libvroc-core.a $$(LIBS) $$(TEST_LIBS)
endef

$(eval $(call BUILD,build,))
$(eval $(call BUILD,build-san,$(SAN)))
$(eval $(call BUILD,build-val,$(VAL)))
# the fuzz target: AFL++'s instrumenting compiler, with the sanitizers
FUZZ_CC ?= afl-clang-fast
$(eval $(call BUILD,build-fuzz,$(SAN),$(FUZZ_CC)))

vroc: build/vroc
	cp build/vroc $@

# ---- tests ----
check: deps
	@$(MAKE) --no-print-directory -j$$(nproc 2>/dev/null || echo 2) check-build
	@sh tests/run.sh

# The long sweeps, with the normal build only (tests/long/run.sh); about 15
# minutes on an idle machine.
check-long: deps
	@$(MAKE) --no-print-directory vroc
	@sh tests/long/run.sh

check-build: vroc man/vroc.1 build-san/vroc build-val/vroc build/tests/wavtool \
             build-san/tests/fuzz_mesh \
             $(addprefix build/tests/,$(CORE_TESTS) $(MESH_TESTS) $(UPPER_TESTS)) \
             $(addprefix build-san/tests/,$(CORE_TESTS) $(MESH_TESTS) $(UPPER_TESTS))

# The sound tests' reader of WAV files (its own parser, not the libsndfile vroc
# writes them with), built once for both builds' script tests.
build/tests/wavtool: tests/wavtool.c tests/tone.h build/flags
	@mkdir -p $(@D)
	$(CC) $(BASE) -o $@ $< -lm

# The scenes' trace hashes (tests/hashes.sh checks them): recorded anew only after a
# change meant to change the simulation, and the commit says why.
record-hashes: vroc
	@sh tests/hashes.sh --record

# ---- benchmarks ----
build/bench/%: bench/%.c bench/bench.h build/libvroc.a build/libvroc-mesh.a build/libvroc-core.a build/flags
	@mkdir -p build/bench
	$(CC) $(CFLAGS_ALL) -O2 -o $@ $< build/libvroc.a build/libvroc-mesh.a build/libvroc-core.a $(LIBS)

build/bench/bullet_gas: bench/bullet_gas.cpp
	@mkdir -p build/bench
	$(CXX) -std=c++17 -O2 -Wall -Wextra -Werror $(shell pkg-config --cflags bullet) -o $@ $< \
	    $(shell pkg-config --libs bullet)

bench: deps
	@sh tools/deps.sh bench
	@$(MAKE) --no-print-directory vroc $(addprefix build/bench/,$(BENCHES)) $(BULLET)
	@sh bench/run.sh

# ---- fuzzing: AFL++ campaigns of FUZZ_TIME seconds each in a scratch folder,
# of FUZZ_TARGETS (script obj stl off ply); what they find goes into
# tests/fuzz/regress/, which check replays (tools/fuzz.sh) ----
FUZZ_TIME ?= 60
FUZZ_TARGETS ?= script obj stl off ply
fuzz:
	@sh tools/deps.sh fuzz
	@$(MAKE) --no-print-directory build-fuzz/vroc build-fuzz/tests/fuzz_mesh
	@FUZZ_TIME=$(FUZZ_TIME) FUZZ_TARGETS="$(FUZZ_TARGETS)" sh tools/fuzz.sh

# ---- the main job ----
demo: deps
	@$(MAKE) --no-print-directory vroc
	@mkdir -p frames
	./vroc -b scenes/simple.vroc -c 'output = "frames"; record = on; collision_sound = knock' \
	    -c 'soundtrack = "frames/simple.wav"; movie = "frames/simple.mp4"; run 30; stats'
	@echo "demo: stereo frames of the Simple scene are in frames/, and a movie of them"
	@echo "      with the sound of the balls on the table: frames/simple.mp4"

deps:
	@sh tools/deps.sh

install: vroc man/vroc.1
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(MANDIR) $(DESTDIR)$(SCENEDIR)
	install -m 755 vroc $(DESTDIR)$(BINDIR)/vroc
	install -m 644 man/vroc.1 $(DESTDIR)$(MANDIR)/vroc.1
	install -m 644 scenes/*.vroc scenes/*.csv scenes/*.obj scenes/*.off scenes/*.ply $(DESTDIR)$(SCENEDIR)/

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/vroc $(DESTDIR)$(MANDIR)/vroc.1
	rm -rf $(DESTDIR)$(PREFIX)/share/vroc

clean:
	rm -rf build build-san build-val build-fuzz vroc tests/out

-include $(wildcard build*/core/*.d build*/mesh/*.d build*/shell/*.d build*/view/*.d build*/sound/*.d build*/hand/*.d build*/tests/*.d)
