"""Sweeps the example airliner's wing tip chord over 50 values and prints the wing's volume
and reference area for each, then what the geometry cache did: the wing is rebuilt for
every variant, the fuselage and the tails are built once.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/tip_chord_sweep.py
"""
import os
import sys
import time

import airshape

here = os.path.dirname(os.path.abspath(__file__))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "generic-airliner.xml")
config = airshape.Configuration.open(path)
wing = config.wings["Wing"]
tip = wing.sections[-1].elements[0].transformation.scaling
for fuselage in config.fuselages:  # built once here; an edit of the wing leaves it alone
    fuselage.volume

print(f"{'tip chord [m]':>14} {'volume [m3]':>12} {'ref. area [m2]':>15} {'time [ms]':>10}")
start = time.perf_counter()
for i in range(50):
    chord = 1.0 + 0.04 * i
    began = time.perf_counter()
    tip.x = chord  # the airfoil's chord-wise scaling
    tip.z = chord  # and its thickness, so that the section keeps its shape
    volume, area = wing.volume, wing.reference_area("x-y")
    print(f"{chord:14.2f} {volume:12.4f} {area:15.4f} {1000 * (time.perf_counter() - began):10.1f}")
print(f"50 variants in {time.perf_counter() - start:.2f} s")

statistics = config.cache_statistics()
print(f"cache: {statistics['built']} built, {statistics['reused']} reused, {statistics['invalidated']} invalidated")
for key, builds in sorted(statistics["builds_by_key"].items()):
    print(f"  {key:32} built {builds} time{'s' if builds > 1 else ''}")
