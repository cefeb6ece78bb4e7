#!/bin/bash
# Issue 39: the element test (biaxial, 50 kPa, 1000 grains, mu 0.5, no rolling resistance) on
# dimers of aspect 1.5; run from this folder (about 1 h on one core of a Zen 5).
trapdem element base.toml --out dimer --set 'particles.shape.kind="dimer"' --set particles.shape.aspect=1.5 --threads 1 --quiet
