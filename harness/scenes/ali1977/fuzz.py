"""Ali (1977)'s part of the fuzz (``harness/fuzz.py``): the K.E.D. programs' entry points in
legacy and port, the SSP routines, the argument dataclasses; the names their call texts use;
the check a corrected cognate must pass (its coupler point on the source's); the listing poles
(each program's geometry driven onto, and a few ulps off, a zero of its listing's Cramer
determinant at a grid angle: ``poles.py``), whose every returned deflection must lie within the
bound the engine states, against the listing's equations in 60 digits (``exact.listing``)."""
from __future__ import annotations

from ....port.ali1977.quirks import Quirks
from ...fuzz_calls import (ANGLES, CONTAINER, FLAG, FLOAT, INT, MATRIX, QUIRKS, VECTOR, Arg, Call, Entry, angles,
                           any_seed, near, num, quirk_set)

#: input-angle steps (deg) of the legacy grids: 0.0018 gives 200001 angles, one more than allowed
STEPS = ("20.0", "10.0", "1.0", "0.1", "45.0", "360.0", "7.5", "0.0018")


def ked_lengths(rng) -> list[str]:
    """l1..l5 (in) of a K.E.D. four-bar: near the example; the example scaled as a family
    (1e-7 to 1e7: the domain's limits, 1e-6 and 1e6 in, and beyond); a coupler triangle of
    any shape (l2 from 0.02 to 5 times l3); or a four-bar on a toggle (l1 + l5 = l3 + l4 or
    l5 - l1 = |l3 - l4|), exactly or a few ulps or 1e-9 off."""
    example = (10.0, 10.0, 30.0, 25.0, 30.0)
    kind = rng.choice(("near", "near", "scaled", "triangle", "toggle"))
    if kind == "scaled":
        factor = 10.0 ** rng.uniform(-7.0, 6.6)
        return [repr(v * factor) for v in example]
    values = [float(near(rng, v, spread=0.15)) for v in example]
    if kind == "triangle":
        values[1] = values[2] * 10.0 ** rng.uniform(-1.7, 0.7)
    elif kind == "toggle":
        l1, _, l3, l4, _ = values
        target = l3 + l4 - l1 if rng.random() < 0.5 else l1 + abs(l3 - l4)
        nudge = rng.choice((0.0, 0.0, 2.0**-52, -2.0**-52, 4 * 2.0**-52, 1e-9, -1e-9))
        values[4] = target * (1.0 + nudge)
    return [repr(v) for v in values]


def legacy_ked(func: str, mass: str):
    """ali1977.case{1,2,3}_{source,cognate}: keyword parameters, printed values as defaults."""
    def spec(rng):
        names = ("l1", "l2", "l3", "l4", "l5")
        args = [Arg(name, value, FLOAT, True) for name, value in zip(names, ked_lengths(rng))]
        mass_value = num(rng, 0.0, 10.0) if mass == "mass_lbf" else num(rng, 0.0, 0.3)
        args += [Arg("alp", ked_alp(rng), FLOAT, True),
                 Arg("rpm", rng.choice(["300.0", "400.0", num(rng, -3000, 5000)]), FLOAT, True),
                 Arg(mass, mass_value, FLOAT, True),
                 Arg("area", num(rng, 0.01, 1.0), FLOAT, True),
                 Arg("modulus", num(rng, 1e6, 3e7, 0), FLOAT, True),
                 Arg("inertia", num(rng, 1e-4, 0.1, 6), FLOAT, True),
                 Arg("step_deg", rng.choice(STEPS + (num(rng, 0.5, 400),)), FLOAT, True)]
        return Call(f"ali1977.{func}", args)
    return spec


def ked_alp(rng) -> str:
    """The coupler point's angle (rad): any quadrant, or on an axis."""
    return rng.choice([num(rng, -6.3, 6.3), num(rng, -6.3, 6.3), "0.0", "np.pi", "-np.pi / 2", "3 * np.pi / 2"])


def lengths_call(rng) -> Call:
    return Call("Lengths", [Arg(None, value, FLOAT) for value in ked_lengths(rng)])


def section_call(rng) -> Call:
    return Call("Section", [Arg(None, num(rng, 0.01, 1.0), FLOAT), Arg(None, num(rng, 1e6, 3e7, 0), FLOAT),
                            Arg(None, num(rng, 1e-4, 0.1, 6), FLOAT)])


def port_ked(module: str, func: str, case: int, presets: tuple):
    """port.ali1977.case*: deg plus lengths, alp, rpm, mass/density, section, quirks (and n)."""
    def spec(rng):
        args = [Arg(None, angles(rng), ANGLES)]
        if case == 3:
            args.append(Arg("n", str(rng.randint(1, 40)), INT, True))
        args += [Arg("lengths", lengths_call(rng), CONTAINER, True),
                 Arg("alp", rng.choice(["None", ked_alp(rng)]), FLOAT, True),
                 Arg("rpm", rng.choice(["300.0", num(rng, -3000, 5000)]), FLOAT, True),
                 Arg("mass_lbf" if case == 1 else "density",
                     num(rng, 0.0, 10.0) if case == 1 else num(rng, 0.0, 0.3), FLOAT, True),
                 Arg("section", section_call(rng), CONTAINER, True),
                 Arg("quirks", quirk_set(rng, _quirk_names(), ("PRINTED", "CORRECTED") + presets), QUIRKS, True)]
        if func == "case3_source":
            args.append(Arg("all_nodes", rng.choice(["False", "True"]), FLAG, True))
        return Call(f"{module}.{func}", args)
    return spec


def mprd_spec(rng) -> Call:
    n, m, l = (rng.randint(1, 4) for _ in range(3))
    msa, msb = rng.choice([0, 0, 1, 2]), rng.choice([0, 0, 1, 2])
    m = n if msa else m
    l = m if msb else l
    size = {0: lambda r, c: r * c, 1: lambda r, c: r * (r + 1) // 2, 2: lambda r, c: r}
    return Call("ali1977.mprd", [Arg(None, f"rand(({size[msa](n, m)},), {any_seed(rng)})", VECTOR),
                                Arg(None, f"rand(({size[msb](m, l)},), {any_seed(rng)})", VECTOR),
                                *[Arg(None, str(v), INT) for v in (n, m, l)],
                                Arg("msa", str(msa), INT), Arg("msb", str(msb), INT)])


def _quirk_names() -> list[str]:
    return Quirks.names()


#: the listing's quirks of each program, as call text (the listing poles' port calls)
LISTING_TEXT = {"case1_source": "PRINTED", "case1_cognate": "PRINTED",
                "case2_source": "port.ali1977.case2.LISTING", "case2_cognate": "port.ali1977.case2.COGNATE_LISTING",
                "case3_source": "port.ali1977.case3.LISTING", "case3_cognate": "port.ali1977.case3.COGNATE_LISTING"}
PORT_TEXT = {"case1_source": "port.ali1977.case1.source_case1", "case1_cognate": "port.ali1977.case1.cognate_case1",
             "case2_source": "port.ali1977.case2.case2_source", "case2_cognate": "port.ali1977.case2.case2_cognate",
             "case3_source": "port.ali1977.case3.case3_source", "case3_cognate": "port.ali1977.case3.case3_cognate"}


def _f32(rng, lo: float, hi: float) -> str:
    """A REAL*4 number in [lo, hi] (the listings' literals and weights are), as text."""
    import numpy as np
    return repr(float(np.float32(rng.uniform(lo, hi))))


def pole_geometry(rng, program: str) -> tuple[list[float], float, float]:
    """(l1..l5 in, alp rad, the grid angle in deg) with ``program``'s listing determinant at a
    zero there (``poles.pole_alps``), exactly or 1 to 16 ulps off (two calls in five), or 2^10 to
    2^46 ulps off (where R1 is 1e-13 to 1e-2 of its terms); a four-bar near the example (Case
    III: l2 over 8 in).  None where eight tries find no pole."""
    import numpy as np

    from ....port.ali1977.fourbar import Lengths
    from . import poles
    for _ in range(8):
        links = [float(near(rng, v, spread=0.3)) for v in (10.0, 14.0, 30.0, 25.0, 30.0)]
        links[1] = max(links[1], 9.0) if program.startswith("case3") else links[1]
        at = float(rng.choice((60.0, 100.0, 120.0, 200.0, 240.0, 300.0)))
        found = poles.pole_alps(program, at, Lengths(*links), grid=37)
        if found:
            alp, off = rng.choice(found), rng.choice((0, 1, -1, 16, -16)) if rng.random() < 0.4 else 0
            if not off:
                off = rng.choice((1, -1)) * round(2.0 ** rng.uniform(10.0, 46.0))
            return links, alp + off * float(np.spacing(alp)) if abs(off) > 16 else poles.nudged(alp, off), at
    return None


def pole_ked(program: str, port: bool):
    """The listing poles: ``program`` in legacy (``ali1977.<program>``, on the grid of step 20 deg)
    or in the port with its listing's bugs (at the pole's angle and two others), the geometry on
    a zero of the listing's determinant (``pole_geometry``), REAL*4 section, weight and speed."""
    def spec(rng):
        geometry = pole_geometry(rng, program)
        links, alp, at = geometry if geometry else ([10.0, 14.0, 30.0, 25.0, 30.0], 1.0, 100.0)
        weight = _f32(rng, 0.5, 5.0) if program.startswith("case1") else _f32(rng, 0.02, 0.2)
        area = _f32(rng, 0.05, 1.0)
        if port:
            args = [Arg(None, f"np.array([0.0, {at!r}, {at + 20.0!r}])", ANGLES)]
            args += [Arg("n", "5", INT)] if program.startswith("case3") else []
            args += [Arg("lengths", Call("Lengths", [Arg(None, repr(v), FLOAT) for v in links]), CONTAINER)]
        else:
            args = [Arg(name, repr(v), FLOAT) for name, v in zip(("l1", "l2", "l3", "l4", "l5"), links)]
        args += [Arg("alp", repr(alp), FLOAT), Arg("rpm", str(rng.randint(100, 900)) + ".0", FLOAT),
                 Arg("mass_lbf" if program.startswith("case1") else "density", weight, FLOAT)]
        if port:
            args += [Arg("section", Call("Section", [Arg(None, area, FLOAT), Arg(None, _f32(rng, 1e6, 3e7), FLOAT),
                                                     Arg(None, _f32(rng, 1e-4, 0.05), FLOAT)]), CONTAINER),
                     Arg("quirks", LISTING_TEXT[program], QUIRKS)]
            return Call(PORT_TEXT[program], args)
        args += [Arg("area", area, FLOAT), Arg("modulus", _f32(rng, 1e6, 3e7), FLOAT),
                 Arg("inertia", _f32(rng, 1e-4, 0.05), FLOAT), Arg("step_deg", "20.0", FLOAT)]
        return Call(f"ali1977.{program}", args)
    return spec


def _within_bound(program: str):
    """The check of a listing pole's call: every deflection vector it returned (dx, dy, extender
    * rot) within the ``error_bound`` it states of the program's own equations in 60 digits (the
    listing's quirks, or the call's)."""
    def check(arguments, result) -> str | None:
        import numpy as np

        from ....port.ali1977.fourbar import Lengths
        from ....port.ali1977.structure import Section
        from . import exact, poles
        positional, named = arguments
        if "lengths" in named:
            lengths, section, quirks, deg = named["lengths"], named["section"], named["quirks"], positional[0]
        else:
            lengths = Lengths(*(named[k] for k in ("l1", "l2", "l3", "l4", "l5")))
            section = Section(named["area"], named["modulus"], named["inertia"])
            quirks, deg = poles.LISTINGS[program][0], result["deg"]
        weight = named["mass_lbf" if program.startswith("case1") else "density"]
        for k, angle in enumerate(np.asarray(deg, dtype=float)):
            try:
                ref = exact.listing(program, float(angle), lengths, named["alp"], named["rpm"], weight, section, quirks,
                                    n=int(named.get("n", 5)))
            except (ArithmeticError, ZeroDivisionError):
                continue
            truth = np.array([ref["dx"], ref["dy"], ref["extender"] * ref["rot"]])
            got = np.array([result["dx"][k], result["dy"][k], ref["extender"] * result["rot"][k]])
            scale = np.linalg.norm(truth)
            error = np.linalg.norm(got - truth) / scale if scale else np.linalg.norm(got)
            if not error <= result["error_bound"][k]:
                return (f"at {angle:g} deg the deflection is {error:.3g} off the listing's equations in 60 digits, "
                        f"over its bound {result['error_bound'][k]:.3g}")
        return None
    return check


CASE2 = ("port.ali1977.case2.LISTING", "port.ali1977.case2.COGNATE_LISTING")
CASE3 = ("port.ali1977.case3.LISTING", "port.ali1977.case3.COGNATE_LISTING")
LEGACY = ("case1_source", "case1_cognate", "case2_source", "case2_cognate", "case3_source", "case3_cognate")

ENTRIES = [Entry(f"ali1977.{f}", legacy_ked(f, "mass_lbf" if f.startswith("case1") else "density"), angles=True)
           for f in LEGACY] + [
    Entry("ali1977.gmtra", lambda rng: Call("ali1977.gmtra", [
        Arg(None, f"rand(({rng.randint(1, 5)}, {rng.randint(1, 5)}), {any_seed(rng)})", MATRIX)])),
    Entry("ali1977.mprd", mprd_spec),
    Entry("ali1977.loc", lambda rng: Call("ali1977.loc", [Arg(None, str(rng.randint(1, 6)), INT) for _ in range(4)]
                                         + [Arg(None, str(rng.randint(0, 2)), INT)])),
    Entry("ali1977.angle_grid", lambda rng: Call("ali1977.angle_grid", [Arg(None, num(rng, 0.5, 400.0), FLOAT)])),
    Entry("port.ali1977.case1.source_case1", port_ked("port.ali1977.case1", "source_case1", 1, ()), angles=True),
    Entry("port.ali1977.case1.cognate_case1", port_ked("port.ali1977.case1", "cognate_case1", 1, ()), angles=True,
          check="cognate"),
    Entry("port.ali1977.case2.case2_source", port_ked("port.ali1977.case2", "case2_source", 2, CASE2), angles=True),
    Entry("port.ali1977.case2.case2_cognate", port_ked("port.ali1977.case2", "case2_cognate", 2, CASE2), angles=True,
          check="cognate"),
    Entry("port.ali1977.case3.case3_source", port_ked("port.ali1977.case3", "case3_source", 3, CASE3), angles=True),
    Entry("port.ali1977.case3.case3_cognate", port_ked("port.ali1977.case3", "case3_cognate", 3, CASE3), angles=True,
          check="cognate"),
    Entry("port.ali1977.fourbar.Lengths", lengths_call),
    Entry("port.ali1977.case1.Section", section_call),
] + [Entry(f"listing pole: {'port' if port else 'ali1977'}.{program}", pole_ked(program, port), angles=True,
           check=f"pole:{program}") for program in LISTING_TEXT for port in (False, True)]

#: every program once at its example, in both quirk modes (compiles the kernels)
WARM_UP = tuple(f"{engine}(np.arange(0.0, 360.0, 90.0), quirks={mode})" for mode in ("PRINTED", "CORRECTED")
                for engine in ("port.ali1977.case1.source_case1", "port.ali1977.case1.cognate_case1",
                               "port.ali1977.case2.case2_source", "port.ali1977.case2.case2_cognate",
                               "port.ali1977.case3.case3_source", "port.ali1977.case3.case3_cognate"))


def namespace() -> dict:
    """The names Ali's call texts use; ``inputs`` and ``quirks``: its dataclass and quirk
    instances (the fuzz offers them to other theses' calls as hostile values)."""
    import linkrepro.port.ali1977.case1  # noqa: F401 (reached through ``port``)
    import linkrepro.port.ali1977.case2  # noqa: F401 (reached through ``port``)
    import linkrepro.port.ali1977.case3  # noqa: F401 (reached through ``port``)
    import linkrepro.port.ali1977.fourbar  # noqa: F401 (reached through ``port``)
    from linkrepro import port
    from linkrepro.legacy import ali1977
    from linkrepro.port.ali1977.case1 import EXAMPLE, Section
    from linkrepro.port.ali1977.fourbar import Lengths
    from linkrepro.port.ali1977.quirks import CORRECTED, PRINTED
    return {"port": port, "ali1977": ali1977, "Section": Section, "Lengths": Lengths, "PRINTED": PRINTED,
            "CORRECTED": CORRECTED, "inputs": (EXAMPLE.lengths, EXAMPLE.section), "quirks": (PRINTED, CORRECTED)}


def _cognate_coincides(arguments, result) -> str | None:
    """With the cognate's turn corrected (cognate_beta_quadrant off) and double storage, the
    cognate's coupler point is the source's at every angle (Roberts-Chebyshev)."""
    import numpy as np
    quirks = arguments[1].get("quirks")
    if quirks is None or quirks.cognate_beta_quadrant or quirks.real4_storage:
        return None
    gap = np.hypot(result["cxp"] - result["xp"], result["cyp"] - result["yp"])
    scale = np.abs(np.concatenate([result["xp"], result["yp"]])).max(initial=1e-300)
    if gap.max() > 1e-9 * scale:
        return f"the cognate's coupler point is {gap.max():.3g} in off the source's (scale {scale:.3g} in)"
    return None


CHECKS = {"cognate": _cognate_coincides, **{f"pole:{program}": _within_bound(program) for program in LISTING_TEXT}}
