"""The parameters of a fit: NAME=OPTION[,OPTION...]:LOW:HIGH[:log].

The optimiser works in scaled coordinates u in [0, 1] per parameter, linear in the value or in its
logarithm (':log', for a quantity known only to its order of magnitude, such as a yield stress), so that
one finite-difference step and one trust radius suit every parameter.
"""
import math


class ParamError(Exception):
    """A parameter specification that cannot be used: the message names it."""


class Param:
    def __init__(self, name, options, low, high, log=False):
        self.name, self.options, self.low, self.high, self.log = name, list(options), low, high, log

    def value(self, u):
        u = min(max(u, 0.0), 1.0)
        if self.log:
            return math.exp(math.log(self.low) + u * (math.log(self.high) - math.log(self.low)))
        return self.low + u * (self.high - self.low)

    def scaled(self, x):
        if self.log:
            return (math.log(x) - math.log(self.low)) / (math.log(self.high) - math.log(self.low))
        return (x - self.low) / (self.high - self.low)

    def dvalue_du(self, u):
        """d value / d u: turns the scaled covariance into the parameter's."""
        if self.log:
            return self.value(u) * (math.log(self.high) - math.log(self.low))
        return self.high - self.low

    def indent_options(self, x):
        """The options that set this parameter to x, in indent's command-line form."""
        out = []
        for opt in self.options:
            out += [f"-{opt}", f"{x:.12g}"]
        return out


def parse(text):
    """'E=film_young,substrate_young:40:120' or 'yield=film_yield:0.05:2:log' -> Param."""
    name, sep, rest = text.partition("=")
    parts = rest.split(":")
    if not sep or not name.strip() or len(parts) not in (3, 4):
        raise ParamError(f"--param {text!r}: expected NAME=OPTION[,OPTION...]:LOW:HIGH[:log]")
    options = [o.strip().lstrip("-") for o in parts[0].split(",")]
    if any(not o for o in options):
        raise ParamError(f"--param {text!r}: an empty option name")
    try:
        low, high = float(parts[1]), float(parts[2])
    except ValueError:
        raise ParamError(f"--param {text!r}: the bounds {parts[1]!r} and {parts[2]!r} are not numbers") from None
    if not (math.isfinite(low) and math.isfinite(high)) or not low < high:
        raise ParamError(f"--param {text!r}: the lower bound must be below the upper one")
    log = len(parts) == 4
    if log and parts[3] != "log":
        raise ParamError(f"--param {text!r}: the fourth field can only be 'log'")
    if log and low <= 0:
        raise ParamError(f"--param {text!r}: a log-scaled parameter needs a positive lower bound")
    return Param(name.strip(), options, low, high, log)


def check_unique(params):
    names, options = set(), set()
    for p in params:
        if p.name in names:
            raise ParamError(f"--param {p.name}: given twice")
        names.add(p.name)
        for o in p.options:
            if o in options:
                raise ParamError(f"--param {p.name}: option -{o} is already set by another parameter")
            options.add(o)
