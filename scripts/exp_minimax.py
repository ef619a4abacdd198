#!/usr/bin/python3
"""Minimax coefficients of the x86 kernels' vector exp (runtime/core/kernel/exp_x86.hpp).

e^r - 1 = r + r^2 P(r) on |r| <= 1.0001 a (a = ln2/2 for exp4, ln2/32 for exp8): P by the Remez
exchange on the error r^2 (P_exact - P) in 50-digit decimal arithmetic, then the coefficients
rounded to double and the error measured again with them. Prints the coefficients (c2, c3, ...)
and both errors. Run: /usr/bin/python3 scripts/exp_minimax.py [--check runtime/core/kernel/exp_x86.hpp]
"""
import math
import sys
from decimal import Decimal as D, getcontext

getcontext().prec = 50
LN2 = D(2).ln()


def p_exact(r):
    """(e^r - 1 - r) / r^2 by its series (r != 0)"""
    term, total, k = D(1) / 2, D(1) / 2, 3
    while abs(term) > D(10) ** -48:
        term = term * r / k
        total += term
        k += 1
    return total


def solve(rows, rhs):
    n = len(rhs)
    m = [row[:] + [rhs[i]] for i, row in enumerate(rows)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(n):
            if r != c:
                f = m[r][c] / m[c][c]
                for k in range(c, n + 1):
                    m[r][k] -= f * m[c][k]
    return [m[i][n] / m[i][i] for i in range(n)]


def power(x, j):
    return D(1) if j == 0 else x ** j


def error(coefficients, x):
    return x * x * (p_exact(x) - sum(D(c) * power(x, j) for j, c in enumerate(coefficients))) if x != 0 else D(0)


def remez(half_width, degree, samples=4000, iterations=10):
    n = degree + 2
    points = sorted(half_width * D(math.cos(math.pi * (2 * i + 1) / (2 * n))) for i in range(n))
    grid = [-half_width + 2 * half_width * D(i) / samples for i in range(samples + 1)]
    for _ in range(iterations):
        rows = [[power(x, j) for j in range(degree + 1)] + [D((-1) ** i) / (x * x)] for i, x in enumerate(points)]
        solution = solve(rows, [p_exact(x) for x in points])
        coefficients = solution[:degree + 1]
        errors = [error(coefficients, x) for x in grid]
        extrema = [0] + [i for i in range(1, samples) if (errors[i] - errors[i - 1]) * (errors[i + 1] - errors[i]) <= 0
                         and errors[i] != 0] + [samples]
        if len(extrema) >= n:
            points = [grid[i] for i in sorted(sorted(extrema, key=lambda i: -abs(errors[i]))[:n])]
    exact_error = max(abs(e) for e in errors)
    rounded = [float(c) for c in coefficients]
    rounded_error = max(abs(error(rounded, x)) for x in grid)
    return rounded, float(exact_error), float(rounded_error)


# --check FILE: every coefficient, as Python prints it, must appear in FILE (exp_x86.hpp): the
# kernels' literals are this script's output (ctest test_exp_minimax_coefficients)
check_path = sys.argv[2] if len(sys.argv) == 3 and sys.argv[1] == "--check" else None
text = open(check_path).read() if check_path else ""
missing = []
for name, half_width, degree in (("exp4", LN2 / 2, 9), ("exp8", LN2 / 32, 4)):
    coefficients, exact_error, rounded_error = remez(half_width * D("1.0001"), degree)
    print(f"{name}: e^r - 1 = r + r^2 P(r), |r| <= 1.0001 x {float(half_width):.6g}, P of degree {degree}: "
          f"error {exact_error:.3g} (exact coefficients), {rounded_error:.3g} (in double)")
    for j, c in enumerate(coefficients):
        print(f"  c{j + 2} = {c!r}")
        if check_path and repr(c) not in text:
            missing.append(f"{name} c{j + 2} = {c!r}")
if check_path:
    if missing:
        print(f"not in {check_path}: " + ", ".join(missing))
        sys.exit(1)
    print(f"every coefficient is in {check_path}")
