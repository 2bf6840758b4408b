#!/usr/bin/env python3
"""Frequencies, damping and amplitudes of the damped sines in a short record, beyond the Fourier
resolution 1 / T: ESPRIT (Roy and Kailath 1989) on the record's Hankel matrix, with a
stabilisation check over model orders as in operational modal analysis.

A Welch PSD of a 17 ms record resolves 60-120 Hz; two wheel modes 20 Hz apart (the seed's Table 4:
a 163 Hz peak against a 183 Hz mode) need 100 ms or more. A record that is a sum of decaying
sines plus noise is fitted instead: the shift invariance of the signal subspace gives the poles
z = exp((-zeta 2 pi f + i 2 pi f_d) dt) directly. Poles the noise makes move when the model order
changes; the signal's stay. Only those found at every order of a few are kept.

Limits (charts.damped_sines shows where it fails): the record must hold a few periods of the
lowest sine of interest; the noise must stay well below the weakest sine kept; a forced response
that is not a sum of decaying sines (a ramp, a transient of the forcing) takes poles of its own,
which is why the stabilisation check and an amplitude floor are applied.

    from damped_sines import stable_poles
    poles = stable_poles(x, dt, band=(50, 2500), order=24)
"""
import math

import numpy as np
from scipy import signal


def decimated(x, dt, top):
    """x low-passed and resampled to about 4 x top Hz, a linear trend taken out; returns the
    samples and their spacing. Fewer samples keep the SVD small and leave the noise outside the
    band out. The FIR filter runs only where it lies wholly inside the record (a padded edge
    would add a transient no sine explains): the record loses 4 new samples at each end."""
    factor = max(1, int(0.25 / (top * dt)))
    y = signal.detrend(np.asarray(x, dtype=float))
    if factor > 1:
        taps = signal.firwin(8 * factor + 1, 0.8 / factor)
        y = signal.fftconvolve(y, taps, mode="valid")[::factor]
    return y, dt * factor


def esprit_poles(y, dt, order):
    """The order complex poles of record y (spacing dt) by least-squares ESPRIT, with their
    complex amplitudes: y[n] ~ sum_k c_k z_k^n. Returns (z, c)."""
    n = len(y)
    rows = n // 2
    if order >= min(rows, n - rows):
        raise ValueError(f"model order {order} needs more than {2 * order} samples (has {n})")
    hankel = np.lib.stride_tricks.sliding_window_view(y, n - rows + 1)  # rows x (n - rows + 1)
    u, _, _ = np.linalg.svd(hankel, full_matrices=False)
    signal_space = u[:, :order]
    shift = np.linalg.lstsq(signal_space[:-1], signal_space[1:], rcond=None)[0]
    z = np.linalg.eigvals(shift)
    vandermonde = z[None, :] ** np.arange(n)[:, None]
    c = np.linalg.lstsq(vandermonde, y.astype(complex), rcond=None)[0]
    return z, c


def sines_of(z, c, dt):
    """Real sines from complex poles: one per pole of positive frequency, as dicts with
    frequency_hz, damping_ratio (of critical), amplitude (2 |c|, at the record's start)."""
    out = []
    for pole, weight in zip(z, c):
        angle = np.angle(pole)
        if angle <= 0:
            continue
        frequency = angle / (2 * math.pi * dt)
        decay = -math.log(abs(pole)) / dt
        out.append({"frequency_hz": frequency, "damping_ratio": decay / (2 * math.pi * frequency),
                    "amplitude": 2 * abs(weight)})
    return out


def stable_poles(x, dt, band, order=24, orders_more=(4, 8), tolerance=0.005, floor=0.02,
                 max_damping=0.2):
    """The damped sines of record x (spacing dt) in band (Hz), found at model order `order` and
    again, within `tolerance` (relative frequency), at every order + orders_more; weaker than
    `floor` times the strongest kept, or damped (or growing) beyond `max_damping` of critical, left
    out.
    Sorted by frequency; each also carries `rms` (the sine's rms over the record)."""
    y, step = decimated(x, dt, band[1])
    found = []
    for extra in (0,) + tuple(orders_more):
        z, c = esprit_poles(y, step, order + extra)
        found.append([s for s in sines_of(z, c, step) if band[0] <= s["frequency_hz"] <= band[1]
                      and abs(s["damping_ratio"]) <= max_damping])
    kept = [s for s in found[0]
            if all(any(abs(o["frequency_hz"] / s["frequency_hz"] - 1) <= tolerance for o in other)
                   for other in found[1:])]
    duration = step * len(y)
    for s in kept:
        decay = 2 * math.pi * s["frequency_hz"] * s["damping_ratio"]
        mean_square = (1 - math.exp(-2 * decay * duration)) / (2 * decay * duration) if decay else 1
        s["rms"] = s["amplitude"] * math.sqrt(0.5 * mean_square)
    strongest = max((s["rms"] for s in kept), default=0)
    return sorted((s for s in kept if s["rms"] >= floor * strongest),
                  key=lambda s: s["frequency_hz"])
