#!/usr/bin/env python3
"""Generate contact_forces/src/GaussianTailTables.inc.

The Greenwood-Tripp integrals
    F_n(lam) = 1/sqrt(2 pi) * int_lam^inf (s - lam)^n exp(-s^2/2) ds
are evaluated here, in 40-digit arithmetic, from their special-function form
    F_n(lam) = Gamma(n+1)/sqrt(2 pi) * exp(-lam^2/4) * U(n + 1/2, lam)
(U = Whittaker's parabolic cylinder function, DLMF 12.5.1), and tabulated for
n = 0, 1/2, 1, 3/2, 2, 5/2 as piecewise Chebyshev series of log F_n on unit
intervals of lam in [LAM_MIN, LAM_ZERO). Below LAM_MIN the code uses the
large-overlap expansion F_n(-a) ~ sum_k C(n,2k) (2k-1)!! a^(n-2k) (the Gaussian
moments; the neglected truncation of the Gaussian at s = lam is O(exp(-a^2/2))),
whose coefficients are written too. Above LAM_ZERO every F_n is below 1e-299 and
the code returns 0.

Needs python3 with mpmath (Debian: python3-mpmath). Run from the repository root:
    python3 contact_forces/tools/gen_gaussian_tail_tables.py > contact_forces/src/GaussianTailTables.inc
The run checks its own output (printed to stderr): the U-function form against
direct tanh-sinh quadrature, and the truncated tables against the U-function form
at points that are not Chebyshev nodes.
"""
import random
import sys

from mpmath import mp, mpf, sqrt, pi, exp, log, cos, pcfu, gamma, quad, inf, binomial

mp.dps = 40

ORDERS = [mpf(k) / 2 for k in range(6)]  # 0, 1/2, 1, 3/2, 2, 5/2
LAM_MIN = -32  # first table piece starts here
LAM_ZERO = 37  # F_n(lam) < 1e-299 for lam >= LAM_ZERO, all tabulated n
WIDTH = 1  # piece width
NCOEF = 16  # Chebyshev coefficients kept per piece (degree 15)
NSAMPLE = 24  # Chebyshev nodes sampled per piece
NEG_TERMS = 8  # terms of the large-overlap expansion


def tail(n, lam):
    lam = mpf(lam)
    return gamma(n + 1) / sqrt(2 * pi) * exp(-lam * lam / 4) * pcfu(n + mpf(1) / 2, lam)


def tail_quad(n, lam):
    lam = mpf(lam)
    if lam >= 0:
        # Integrand peaks at t = 0 with width ~ 1/(1 + lam); the factor exp(-lam^2/2) is
        # taken out so that quad's error control works on O(1) numbers.
        w = 1 / (1 + lam)
        f = lambda t: t**n * exp(-t * t / 2 - lam * t)
        return quad(f, [0, w / 4, w, 3 * w, 10 * w, 40 * w, inf]) * exp(-lam * lam / 2) / sqrt(2 * pi)
    # Integrand peaks near t = -lam with width ~ 1.
    f = lambda t: t**n * exp(-(t + lam) ** 2 / 2)
    return quad(f, [0, max(mpf(0), -lam - 8), -lam, -lam + 8, inf]) / sqrt(2 * pi)


def cheb_coeffs(fn, a, b, nsample):
    thetas = [pi * (k + mpf(1) / 2) / nsample for k in range(nsample)]
    vals = [fn((b - a) / 2 * cos(th) + (b + a) / 2) for th in thetas]
    coeffs = []
    for j in range(nsample):
        s = sum(v * cos(j * th) for v, th in zip(vals, thetas)) * 2 / nsample
        coeffs.append(s)
    coeffs[0] /= 2
    return coeffs


def cheb_eval(coeffs, t):
    b1 = mpf(0)
    b2 = mpf(0)
    for c in reversed(coeffs[1:]):
        b1, b2 = 2 * t * b1 - b2 + c, b1
    return t * b1 - b2 + coeffs[0]


def neg_expansion(n):
    out = []
    dfact = mpf(1)  # (2k-1)!!
    for k in range(NEG_TERMS):
        if k > 0:
            dfact *= 2 * k - 1
        out.append(binomial(n, 2 * k) * dfact)
    return out


def main():
    log_err = sys.stderr
    # 1. The special-function form against direct quadrature.
    worst = mpf(0)
    for n in ORDERS:
        for lam in [-20, -3, -0.5, 0, 0.7, 2, 4, 9, 25]:
            a, b = tail(n, lam), tail_quad(n, lam)
            worst = max(worst, abs(a / b - 1))
    print(f"U-form vs tanh-sinh quadrature: max rel diff {mp.nstr(worst, 3)}", file=log_err)

    rng = random.Random(20260101)
    npieces = (LAM_ZERO - LAM_MIN) // WIDTH
    tables = []
    for n in ORDERS:
        pieces = []
        worst_fit = mpf(0)
        worst_tail = mpf(0)
        worst_fit8 = mpf(0)
        for i in range(npieces):
            a = mpf(LAM_MIN + i * WIDTH)
            b = a + WIDTH
            c = cheb_coeffs(lambda x: log(tail(n, x)), a, b, NSAMPLE)
            # Dropped coefficients bound the truncation error in log F (= rel. error in F).
            worst_tail = max(worst_tail, sum(abs(x) for x in c[NCOEF:]))
            kept = c[:NCOEF]
            for _ in range(4):
                x = a + (b - a) * mpf(rng.random())
                t = 2 * (x - a) / (b - a) - 1
                approx = exp(cheb_eval([mpf(float(v)) for v in kept], t))
                err = abs(approx / tail(n, x) - 1)
                worst_fit = max(worst_fit, err)
                if -8 <= x <= 8:
                    worst_fit8 = max(worst_fit8, err)
            pieces.append(kept)
        print(f"n={float(n)}: dropped-coefficient sum {mp.nstr(worst_tail, 3)}, "
              f"max rel err of rounded table at random points {mp.nstr(worst_fit, 3)} "
              f"(|lam| <= 8: {mp.nstr(worst_fit8, 3)})", file=log_err)
        # Large-overlap expansion at the table's lower end.
        e = neg_expansion(n)
        aa = mpf(-LAM_MIN)
        approx = sum(ek * aa ** (n - 2 * k) for k, ek in enumerate(e))
        print(f"n={float(n)}: overlap expansion rel err at lam={LAM_MIN}: "
              f"{mp.nstr(abs(approx / tail(n, LAM_MIN) - 1), 3)}", file=log_err)
        tables.append((pieces, e))

    out = sys.stdout
    out.write("// Generated by contact_forces/tools/gen_gaussian_tail_tables.py -- do not edit.\n")
    out.write("// log F_n(lam), n = 0, 1/2, 1, 3/2, 2, 5/2, on pieces [lam_i, lam_i + 1],\n")
    out.write(f"// lam_i = {LAM_MIN} + i, as Chebyshev series in t = 2 (lam - lam_i) - 1, and the\n")
    out.write("// coefficients C(n,2k) (2k-1)!! of the large-overlap expansion used below the table.\n")
    out.write(f"constexpr int kTailOrders = {len(ORDERS)};\n")
    out.write(f"constexpr double kTableLambdaMin = {LAM_MIN}.0;\n")
    out.write(f"constexpr double kTableLambdaZero = {LAM_ZERO}.0;\n")
    out.write(f"constexpr int kTablePieces = {npieces};\n")
    out.write(f"constexpr int kChebCoeffs = {NCOEF};\n")
    out.write(f"constexpr int kOverlapTerms = {NEG_TERMS};\n")
    out.write("alignas(64) constexpr double kLogTailCheb[kTailOrders][kTablePieces][kChebCoeffs] = {\n")
    for k, (pieces, _) in enumerate(tables):
        out.write(f"    {{  // n = {float(ORDERS[k])}\n")
        for i, c in enumerate(pieces):
            vals = ", ".join(f"{float(v):.17g}" for v in c)
            out.write(f"        {{{vals}}},  // [{LAM_MIN + i}, {LAM_MIN + i + 1}]\n")
        out.write("    },\n")
    out.write("};\n")
    out.write("constexpr double kOverlapExpansion[kTailOrders][kOverlapTerms] = {\n")
    for k, (_, e) in enumerate(tables):
        vals = ", ".join(f"{float(v):.17g}" for v in e)
        out.write(f"    {{{vals}}},  // n = {float(ORDERS[k])}\n")
    out.write("};\n")


if __name__ == "__main__":
    main()
