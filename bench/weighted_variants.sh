#!/bin/sh
# How the simulator's weighted can and mug (the report's section 5.4) are heard by a classifier trained
# on the four original objects only, as the chapter-5 campaign's classifier is: per action, how many of
# the variants' recordings it takes for their original, and for which other object otherwise.
#
#   bench/weighted_variants.sh [ECHOPLAN] [PER_PAIR] [CATALOGUE]
#
# ECHOPLAN: the binary (default build/echoplan); PER_PAIR: recordings per object and action, for the
# training set (seed 1) and for the held-out set (seed 2) alike (default 20); CATALOGUE: the catalogue
# (default: the binary's default, objects/catalogue.yaml). The classifier is `echoplan train`'s default
# (summary-lda) with --no-reject, as the campaign hears: every recording gets an object. With REJECT=1
# (environment) it keeps its reject option instead: the `unknown` column counts the recordings it
# finds unlike every original (docs/perception.md, "Reject").
# Results: docs/simulator.md ("What it does to the main job").
set -eu
echoplan=${1:-build/echoplan}
per_pair=${2:-20}
catalogue_option=""
if [ $# -ge 3 ]; then catalogue_option="--catalogue $3"; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM

originals=pringles_can,coffee_mug,plastic_cup,paper_base
# shellcheck disable=SC2086 # catalogue_option is empty or two words
"$echoplan" dataset $catalogue_option --per-pair "$per_pair" --seed 1 -o "$work/train" \
  --objects "$originals" >/dev/null 2>&1
# shellcheck disable=SC2086
"$echoplan" dataset $catalogue_option --per-pair "$per_pair" --seed 2 -o "$work/held" \
  --objects "$originals,pringles_can_weighted,coffee_mug_weighted" >/dev/null 2>&1
reject_option=--no-reject
with_reject=""
if [ "${REJECT:-}" = 1 ]; then reject_option="" with_reject=", with reject"; fi
# shellcheck disable=SC2086 # reject_option is empty or one word
"$echoplan" train $reject_option --data "$work/train" -o "$work/model.json" >/dev/null 2>&1
echo "classifier trained on the four originals ($per_pair per action, seed 1$with_reject);" \
  "held-out set seed 2"
"$echoplan" evaluate --model "$work/model.json" --data "$work/held" 2>/dev/null
