#!/usr/bin/python3
"""The PyTorch reference for scripts/bench_cnmp_quality (docs/performance.md, "Quality").

Trains one CNMP in PyTorch (float32) on the benchmark's synthetic family, with the training
loop of the public CNMP code (per update: one random demonstration, n observations uniform in
1..5 and one target, drawn disjoint from a permutation of its time steps; Gaussian negative
log-likelihood; Adam), and prints its best validation error. Everything else is train_cnmp's
definition, so that only the framework and the initial weights differ from the project's
figure: the paper's sizes (encoder 3 and decoder 4 Linear layers of 128, ReLU between, decoder
input [mean encoding, context, time], sigma = 0.01 + softplus(raw)), y and the context
standardised with the training demonstrations' mean and standard deviation, time scaled to
[0, 1], the split and the sampler's draws of train_cnmp's seed stream (same seed, same held-out
demonstrations and same training points), and the validation error every 1,000 updates: the
mean over held-out demonstrations of the time-averaged Euclidean error, in data units, of the
prediction from their first point and context. The initial weights are PyTorch's default
(torch.nn.Linear, the same distribution as the project's) from torch.manual_seed(seed).

Usage (Debian's PyTorch: apt-get install python3-torch):
  /usr/bin/python3 scripts/cnmp_reference.py --seed S [--updates U] [--data DIR]
--data: a folder of `scripts/bench_cnmp_quality --write-family DIR` (default: written afresh).
"""
import argparse
import csv
import glob
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import torch
from torch import nn

MASK = (1 << 64) - 1


def mix64(z):
    z = (z + 0x9E3779B97F4A7C15) & MASK
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


class ProjectRng:
    """core/seeds.hpp's SeedTree(root).stream(name): xoshiro256** seeded through SplitMix64."""

    def __init__(self, root, name):
        h = 0xCBF29CE484222325  # FNV-1a of the name
        for byte in name.encode():
            h = ((h ^ byte) * 0x100000001B3) & MASK
        seed = mix64(mix64(root) ^ h)
        self.s = [mix64((seed + i * 0x9E3779B97F4A7C15) & MASK) for i in range(4)]

    def next(self):
        s = self.s
        rotl = lambda x, k: ((x << k) | (x >> (64 - k))) & MASK
        result = (rotl((s[1] * 5) & MASK, 7) * 9) & MASK
        t = (s[1] << 17) & MASK
        s[2] ^= s[0]
        s[3] ^= s[1]
        s[1] ^= s[2]
        s[0] ^= s[3]
        s[2] ^= t
        s[3] = rotl(s[3], 45)
        return result

    def uniform_int(self, lo, hi):  # inclusive, unbiased
        span = hi - lo + 1
        limit = MASK - (MASK % span)
        while True:
            draw = self.next()
            if draw < limit:
                return lo + draw % span


def read_family(folder):
    """Each CSV file as (x: T x 1 time in [0, 1], y: T x 2, context: 1 value), in name order."""
    demos = []
    for path in sorted(glob.glob(os.path.join(folder, "*.csv"))):
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
        values = np.array([[float(v) for v in row] for row in rows[1:]])
        col = {name: i for i, name in enumerate(rows[0])}
        t = values[:, col["t"]]
        x = ((t - t[0]) / (t[-1] - t[0]))[:, None]
        demos.append((x, values[:, [col["y1"], col["y2"]]], values[0, [col["c"]]]))
    if not demos:
        print(f"cnmp_reference.py: --data {folder}: no .csv files there", file=sys.stderr)
        sys.exit(2)
    return demos


def standardiser(rows):  # normaliser.cpp: mean and population standard deviation
    offset = rows.mean(axis=0)
    scale = np.sqrt(((rows - offset) ** 2).mean(axis=0))
    return offset, np.where(scale > 1e-9, scale, 1.0)


def mlp(sizes):  # Linear layers with ReLU between them, none after the last
    layers = []
    for i in range(len(sizes) - 1):
        layers += [nn.Linear(sizes[i], sizes[i + 1]), nn.ReLU()]
    return nn.Sequential(*layers[:-1])


class Cnmp(nn.Module):
    def __init__(self, d_x=1, d_y=2, d_context=1, width=128, min_std=0.01):
        super().__init__()
        self.encoder = mlp([d_x + d_y] + [width] * 3)
        self.decoder = mlp([width + d_context + d_x] + [width] * 3 + [2 * d_y])
        self.d_y, self.min_std = d_y, min_std

    def forward(self, observations, context, query_x):
        r = self.encoder(observations).mean(dim=0)
        n = query_x.shape[0]
        out = self.decoder(torch.cat([r.expand(n, -1), context.expand(n, -1), query_x], dim=1))
        mean, raw = out[:, : self.d_y], out[:, self.d_y :]
        return mean, self.min_std + nn.functional.softplus(raw)


def gaussian_nll(mean, std, target):  # mean over targets and dimensions
    z = (target - mean) / std
    return (torch.log(std) + 0.5 * z * z + 0.5 * math.log(2 * math.pi)).mean()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--updates", type=int, default=200000)
    parser.add_argument("--data", help="family folder (default: written by bench_cnmp_quality)")
    args = parser.parse_args()
    torch.set_num_threads(1)
    if args.data is None:
        tmp = tempfile.TemporaryDirectory()
        args.data = os.path.join(tmp.name, "family")
        script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench_cnmp_quality")
        subprocess.run([script, "--write-family", args.data], check=True)
    demos = read_family(args.data)

    # train_cnmp's split: a Fisher-Yates shuffle from the seed stream, the first 20% held out.
    rng = ProjectRng(args.seed, "train_cnmp")
    for i in range(len(demos), 1, -1):
        j = rng.uniform_int(0, i - 1)
        demos[i - 1], demos[j] = demos[j], demos[i - 1]
    held_out = int(0.2 * len(demos))
    validation, train = demos[:held_out], demos[held_out:]
    y_offset, y_scale = standardiser(np.vstack([y for _, y, _ in train]))
    c_offset, c_scale = standardiser(np.vstack([c for _, _, c in train]))
    f32 = lambda a: torch.tensor(np.asarray(a), dtype=torch.float32)
    points = [f32(np.hstack([x, (y - y_offset) / y_scale])) for x, y, _ in train]
    contexts = [f32((c - c_offset) / c_scale)[None, :] for _, _, c in train]

    torch.manual_seed(args.seed)
    model = Cnmp()
    adam = torch.optim.Adam(model.parameters(), lr=1e-4)

    def validation_error():
        errors = []
        with torch.no_grad():
            for x, y, c in validation:
                first = f32(np.hstack([x[:1], (y[:1] - y_offset) / y_scale]))
                mean, _ = model(first, f32((c - c_offset) / c_scale)[None, :], f32(x))
                predicted = mean.double().numpy() * y_scale + y_offset
                errors.append(np.linalg.norm(predicted - y, axis=1).mean())
        return float(np.mean(errors))

    best, best_update, start = math.inf, 0, time.time()
    for update in range(1, args.updates + 1):
        # batch_sampler.hpp's draws, in its order: n, m (always 1), the demonstration, and a
        # partial permutation of its time steps whose first n are observed and next m targeted.
        n, m = rng.uniform_int(1, 5), rng.uniform_int(1, 1)
        d = rng.uniform_int(0, len(points) - 1)
        steps = points[d].shape[0]
        n = min(n, steps - 1)
        m = min(m, steps - n)
        order = list(range(steps))
        for i in range(n + m):
            j = rng.uniform_int(i, steps - 1)
            order[i], order[j] = order[j], order[i]
        observations = points[d][order[:n]]
        targets = points[d][order[n : n + m]]
        mean, std = model(observations, contexts[d], targets[:, :1])
        loss = gaussian_nll(mean, std, targets[:, 1:])
        adam.zero_grad()
        loss.backward()
        adam.step()
        if update % 1000 == 0 or update == args.updates:
            error = validation_error()
            if error < best:
                best, best_update = error, update
    print(f"seed {args.seed}: best validation error {best:.6g} at update {best_update}"
          f" ({args.updates} updates, {time.time() - start:.1f} s)")


if __name__ == "__main__":
    main()
