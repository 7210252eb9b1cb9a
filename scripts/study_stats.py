"""The paired statistics of the study reports (teacher_report.py, ablation_report.py): two
learners run on the same seeds (common random numbers) compared seed by seed.

sign_test_p, the exact two-sided sign test with ties dropped; paired, the mean difference
with a seeded 95 % percentile bootstrap and the sign test's p; paired_text, the same as text
(interval_text, the mean and interval alone); sign_counts, the seeds where the second is
greater, less and tied.
"""

import math
import random


def sign_test_p(positive, negative):
    """Exact two-sided sign test (ties dropped): twice the smaller binomial tail, at most 1."""
    n = positive + negative
    if n == 0:
        return 1.0
    tail = sum(math.comb(n, k) for k in range(min(positive, negative) + 1)) / 2.0 ** n
    return min(1.0, 2.0 * tail)


def sign_counts(a, b):
    """b - a seed by seed: (how many seeds greater, less, tied)."""
    differences = [y - x for x, y in zip(a, b)]
    positive = sum(d > 0 for d in differences)
    negative = sum(d < 0 for d in differences)
    return positive, negative, len(differences) - positive - negative


def paired(a, b):
    """b - a seed by seed: (mean, low, high, p) with a seeded percentile bootstrap."""
    differences = [y - x for x, y in zip(a, b)]
    n = len(differences)
    mean = sum(differences) / n
    draw = random.Random(1)
    means = sorted(sum(draw.choice(differences) for _ in range(n)) / n for _ in range(10000))
    positive, negative, _ = sign_counts(a, b)
    return mean, means[249], means[9749], sign_test_p(positive, negative)


def interval_text(mean, low, high, digits=1):
    return f"{mean:+.{digits}f} [{low:+.{digits}f}, {high:+.{digits}f}]"


def paired_text(a, b, digits=1):
    mean, low, high, p = paired(a, b)
    return f"{interval_text(mean, low, high, digits)}, p = {p:.2g}"
