#!/usr/bin/env python3
"""Speed of the Python package (a benchmark, not a test): nanoseconds per point of the table
lookups on 10^6 points, the same through a quantity's table method, and the Ctrl-C latency
of a long exact call.

    PYTHONPATH=build/python python3 python/bench/bench_python.py [--tables tables] [--points 1000000]

Each figure is the best of 5 runs (the machine may be shared)."""
import argparse
import os
import signal
import threading
import time

import numpy as np

import brdftab
from brdftab import lookup


def best(f, repeat=5):
    """Best wall time and best CPU time (process_time: what the call costs when the machine
    is shared) of `repeat` runs."""
    wall, cpu = [], []
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        f()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return min(wall), min(cpu)


def interrupt_latency():
    c = np.linspace(0.01, 0.99, 200_000)
    sent = {}

    def fire():
        sent["t"] = time.perf_counter()
        os.kill(os.getpid(), signal.SIGINT)

    threading.Timer(0.3, fire).start()
    try:
        brdftab.h_iso(c, 0.5)
    except KeyboardInterrupt:
        return time.perf_counter() - sent["t"]
    return float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tables", default="tables")
    ap.add_argument("--points", type=int, default=1_000_000)
    a = ap.parse_args()
    n, T = a.points, a.tables
    rng = np.random.default_rng(1)
    mu = rng.uniform(1e-6, 1, n)
    mu2 = rng.uniform(1e-6, 1, n)
    alpha = np.exp(rng.uniform(np.log(0.01), 0, n))
    c = rng.uniform(0, 1, n)
    p = rng.uniform(0.5, 2, n)
    f32 = mu.astype(np.float32), alpha.astype(np.float32)
    cases = [
        ("lookup.microfacet_albedo (GGX, precise)", lambda: lookup.microfacet_albedo(mu, alpha, tables=T)),
        ("lookup.microfacet_albedo (GGX, float32 in/out)", lambda: lookup.microfacet_albedo(*f32, tables=T)),
        ("lookup.microfacet_albedo (GGX, compact)", lambda: lookup.microfacet_albedo(mu, alpha, precise=False, tables=T)),
        ("lookup.microfacet_albedo (gbeckmann, 3-D)",
         lambda: lookup.microfacet_albedo(mu, alpha, p, ndf="gbeckmann", tables=T)),
        ("lookup.microfacet_albedo_avg (GGX)", lambda: lookup.microfacet_albedo_avg(alpha, tables=T)),
        ("lookup.kulla_conty_lobe (GGX)", lambda: lookup.kulla_conty_lobe(mu, mu2, alpha, tables=T)),
        ("lookup.microfacet_albedo_render (GGX, render profile)", lambda: lookup.microfacet_albedo_render(mu, alpha, tables=T)),
        ("lookup.microfacet_albedo_render (GGX, float32 in/out)", lambda: lookup.microfacet_albedo_render(*f32, tables=T)),
        ("lookup.microfacet_albedo_avg_render (GGX)", lambda: lookup.microfacet_albedo_avg_render(alpha, tables=T)),
        ("lookup.kulla_conty_lobe_render (GGX)", lambda: lookup.kulla_conty_lobe_render(mu, mu2, alpha, tables=T)),
        ("lookup.smith_gbeckmann_g1", lambda: lookup.smith_gbeckmann_g1(mu, alpha, 1 + p, tables=T)),
        ("lookup.h_function (iso)", lambda: lookup.h_function(c, mu, tables=T)),
        ("lookup.ls_plane_albedo", lambda: lookup.ls_plane_albedo(c, mu, tables=T)),
        ("Table(demo_exp_cos)", lambda: brdftab.Table(os.path.join(T, "demo.h5"), "demo_exp_cos")(mu, mu2)),
    ]
    print(f"{'function':50s} ns/point wall, cpu ({n} points, best of 5; load {os.getloadavg()[0]:.1f})")
    for name, f in cases:
        f()  # load the tables
        w, c = best(f)
        print(f"{name:50s} {w / n * 1e9:8.1f} {c / n * 1e9:8.1f}")
    m = 20_000
    w, c = best(lambda: brdftab.microfacet_albedo_ggx(mu[:m], alpha[:m], method="table", tables=T), 3)
    print(f"{'microfacet_albedo_ggx(method=table), 4 outputs':50s} {w / m * 1e9:8.1f} {c / m * 1e9:8.1f}")
    lat = interrupt_latency()
    print(f"Ctrl-C latency of a long exact call: {lat * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
