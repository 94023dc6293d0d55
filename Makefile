# Figures for every scenario in configs/: `make figures` (safe with -j2; rebuilds only what changed).
#
#   make figures                       outputs/NAME.svg and outputs/NAME.pdf for each configs/NAME.yaml
#   make -j2 figures FORMATS=svg,png   other formats; OUTPUTS=dir another folder
#   make figures PLOT_OPTIONS="--style print"   any other `sears-paradox plot` options
#   make readme-figures                the figures the README shows (outputs/readme/), and the
#                                      matplotlib they were made with (give PYTHON= of the same environment)
#
# Each figure is remade when its scenario file or any source file of the package changed.
# `plot` leaves a figure whose bytes would not change untouched (its date too), so a stamp
# per scenario (OUTPUTS/.stamps/NAME) records that it is up to date. After changing
# FORMATS, OUTPUTS or PLOT_OPTIONS, run `make -B figures`.

SEARS_PARADOX ?= sears-paradox
PYTHON ?= python3
OUTPUTS ?= outputs
FORMATS ?= svg,pdf
PLOT_OPTIONS ?=

# every scenario, struck by particles or driven by forces
CONFIGS := $(wildcard configs/*.yaml)
SOURCES := $(wildcard rodparadox/*.py rodparadox/*/*.py cli/*.py)
STAMPS := $(patsubst configs/%.yaml,$(OUTPUTS)/.stamps/%,$(CONFIGS))

.PHONY: figures readme-figures

figures: $(STAMPS)

$(OUTPUTS)/.stamps/%: configs/%.yaml $(SOURCES) | $(OUTPUTS)/.stamps
	$(SEARS_PARADOX) plot $< --format $(FORMATS) -o $(OUTPUTS) $(PLOT_OPTIONS)
	@touch $@

$(OUTPUTS)/.stamps:
	@mkdir -p $@

readme-figures:
	@mkdir -p outputs/readme
	$(SEARS_PARADOX) plot fig1 fig2 -o outputs/readme
	$(SEARS_PARADOX) ledger fig2 -o outputs/readme/fig2_ledger.svg
	$(PYTHON) -m rodparadox.handout.readme_pictures outputs/readme
	@$(PYTHON) -c 'import matplotlib; print("matplotlib", matplotlib.__version__)' > outputs/readme/made-with.txt

# The documentation site (the docs extra: pip install -e '.[docs]'), built offline into docs/_build/html:
#   make docs        the gallery's pictures that are out of date redrawn (make gallery), then the site, warnings as errors
#   make gallery     docs/gallery/*.png and docs/gallery.md from configs/ (GALLERY_OPTIONS=--all: every picture again)
DOCS_PYTHON ?= $(if $(wildcard .venv/bin/python),.venv/bin/python,$(PYTHON))
GALLERY_OPTIONS ?=

.PHONY: docs gallery

gallery:
	$(DOCS_PYTHON) docs/gallery.py $(GALLERY_OPTIONS)

docs: gallery
	$(DOCS_PYTHON) -m sphinx -b html -j 1 -W --keep-going docs docs/_build/html
