"""Rahman (1996): the rigid spatial slider crank in Exudyn against the corrected port (scene
rahman1996-multibody).

Exudyn (``harness/multibody.py``) is told only the mechanism: three rigid bodies built from the
port's own data (``CsspInputs``, ``Constants``: lengths, offsets, the nine point masses), a
revolute crank bearing on the ground's z axis, the crank's rotation prescribed (constant speed),
the crank pin, a ball joint from rod to slider, a prismatic guide along k4.  No gravity (the
tables carry none).  From its bodies' accelerations it gives the shaking force (Table 5.3) and
the shaking moment about the crank frame's origin (Table 5.4), sum of m a and of the rate of
change of angular momentum; the drive constraint's reaction is the input torque (Table 5.7).
These are set against the corrected port's (``balance(quirks=CSSP_CORRECTED)``) 'before'
(equal point masses) and 'after' (the balancing QP's masses) columns at the 37 table angles,
each difference stated against the column's peak.

The crank pin is modelled two ways:

- ``universal``: a Hooke joint with one axis along the crank's z (k1) and the other along the
  rod's y, normal to it, so the rod cannot spin about its own axis: the joint the port's
  kinematics reads (the rod frame's fixed orientation to k1);
- ``spherical``: a ball joint, the rod free to spin; its spin is then set by the dynamics.

Units: inch, lbf, second, lbf s^2/in; crank angles in degrees.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ....port.rahman1996.balance import CRANK_DEG, balance, link_masses, principal_moments
from ....port.rahman1996.data import Constants, CsspInputs
from ....port.rahman1996.quirks import CSSP_CORRECTED
from ....port.slider_crank.kinematics import kinematics
from ... import multibody, progress
from ...csv_output import FULL_PRECISION, write_csv
from ...scene import ReportScene

NAME = "rahman1996-multibody"
TITLE = "Rahman (1996): the corrected engine's shaking force, moment and input torque against Exudyn"
#: the compared columns: the table, its quantity, unit, and the port table's 'before' column
#: (``balance``'s ``table``; the 'after' column is the next one)
QUANTITIES = (("5_3", "shaking force", "lbf", 2), ("5_4", "shaking moment", "lbf in", 4),
              ("5_7", "input torque", "lbf in", 10))
MASSES = ("before", "after")
JOINTS = ("universal", "spherical")
#: the step (deg of crank) of the comparison, chosen by ``linkrepro bench``'s knob "Exudyn step
#: (CSSP)" (``bench.exudyn_step``, over STEPS): the largest difference falls as h^2 (7e-5 to 9e-5
#: of the peaks at 1 deg) to about 1e-6 at 0.1 deg, and below to a round-off floor (3e-7 to 8e-7
#: at 0.05 deg), so a finer step buys nothing the comparison needs
STEP_DEG = 0.1
#: the steps of the bench's study, deg
STEPS = (1.0, 0.5, 0.2, 0.1, 0.05)
#: the solver's start-up: the run starts from the port's position and velocities at 0 deg with
#: consistent accelerations, and the implicit scheme's own start-up error dies out as its spectral
#: radius (0.8) a step; measured: one revolution at 0.1 deg (the 10 deg row 100 steps in) agrees
#: with the last of two to the round-off floor, at 0.2 deg (50 steps in) it is 5 times off, at
#: 1 deg 450 times.  So a comparison reads the first revolution where 10 deg of crank is at least
#: START_UP_STEPS steps (its 0 deg row is then the start: Exudyn's accelerations at the port's
#: state; its 360 deg row, the same position, integrated), else the second (``revolutions``)
START_UP_STEPS = 100


@dataclass(frozen=True)
class Solver:
    """Exudyn's implicit generalized-alpha settings (measured: a Newton tolerance of 1e-8 is met
    at every step, 1e-12 is not; spectral radius 1.0 leaves undamped high-frequency noise in
    the constraint forces, 0.8 does not)."""
    newton_tolerance: float = 1e-8
    spectral_radius: float = 0.8


def revolutions(step_deg: float) -> int:
    """The revolutions simulated from 0 deg at a step of ``step_deg`` (deg); the comparison reads
    the last: one where the 10 deg of crank before the first table angle after the start take at
    least ``START_UP_STEPS`` steps, else two."""
    return 1 if int(round(10.0 / step_deg)) >= START_UP_STEPS else 2


def simulate(point_masses, crank_pin: str, step_deg: float = STEP_DEG, inputs: CsspInputs = CsspInputs(),
             solver: Solver = Solver()) -> pd.DataFrame:
    """Exudyn's shaking force (lbf), moment about the origin (lbf in) and input torque (lbf in)
    at the 37 table angles of the last of ``revolutions(step_deg)``, the crank turned at the
    inputs' speed in steps of ``step_deg``; columns as ``QUANTITIES``' tables, and
    ``ground_residual``: the largest |sum of m a + the ground joints' reactions| (lbf) over the
    revolution, Newton's law by Exudyn's own constraint forces.  ``crank_pin``: ``JOINTS``."""
    exu = multibody.require()
    if crank_pin not in JOINTS:
        raise ValueError(f"crank_pin must be one of {JOINTS}, got {crank_pin!r}")
    from exudyn.utilities import (MarkerNodeCoordinate, NodePointGround, ObjectConnectorCoordinate,
                                  RigidBodyInertia, SensorBody, SensorObject)
    c = Constants.of(inputs, real4=False)
    x = np.asarray(point_masses, dtype=float)
    m1, m2, m3 = link_masses(x)
    i1, i2 = (np.array(principal_moments(arms, x[k:k + 3])) for k, arms in ((0, c.crank_arms), (4, c.rod_arms)))
    omega, k4, zhat = c.omega, np.asarray(c.k4), np.array([0.0, 0.0, 1.0])
    start = kinematics(c, np.array([0.0]))
    p, q, r2 = start.P[0], start.Q[0], start.R2[0]

    mbs = exu.SystemContainer().AddSystem()
    ground = mbs.CreateGround(referencePosition=[0.0, 0.0, 0.0])
    crank_cg = p + np.array([c.cg[0], 0.0, 0.0])
    rod_cg = q + r2 @ np.array([c.cg[1], 0.0, 0.0])
    crank = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=m1, inertiaTensor=np.diag(i1)),
                                referencePosition=crank_cg, referenceRotationMatrix=np.eye(3),
                                initialVelocity=np.cross(omega * zhat, crank_cg), initialAngularVelocity=omega * zhat,
                                nodeType=exu.NodeType.RotationRxyz)
    rod = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=m2, inertiaTensor=np.diag(i2)),
                              referencePosition=rod_cg, referenceRotationMatrix=r2,
                              initialVelocity=start.Qd[0] + c.cg[1] * start.ud[0], initialAngularVelocity=start.w2[0])
    # the slider: a point mass at Q (the guide locks its rotation; Exudyn needs a regular inertia)
    slider = mbs.CreateRigidBody(inertia=RigidBodyInertia(mass=m3, inertiaTensor=np.eye(3) * m3),
                                 referencePosition=q, referenceRotationMatrix=np.eye(3), initialVelocity=start.Qd[0])
    bearing = mbs.CreateRevoluteJoint(itemNumbers=[ground, crank], position=[0.0, 0.0, 0.0], axis=zhat,
                                      useGlobalFrame=True)
    # the drive: the crank node's third Tait-Bryan angle = omega t; its multiplier is minus the torque
    fixed = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=mbs.AddNode(NodePointGround()), coordinate=0))
    turned = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=mbs.GetObject(crank)["nodeNumber"], coordinate=5))
    drive = mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[fixed, turned],
                                                    offsetUserFunction=lambda mbs, t, item, offset: omega * t))
    if crank_pin == "universal":
        # Exudyn's generic joint with constrainedAxes [1,1,1,1,0,0] keeps its frame's y axis on
        # the first body normal to its z axis on the second: y = k1 (crank), z = the rod's y
        e = r2[:, 1]
        mbs.CreateGenericJoint(itemNumbers=[crank, rod], position=p, useGlobalFrame=True,
                               rotationMatrixAxes=np.column_stack([np.cross(zhat, e), zhat, e]),
                               constrainedAxes=[1, 1, 1, 1, 0, 0])
    else:
        mbs.CreateSphericalJoint(itemNumbers=[crank, rod], position=p)
    mbs.CreateSphericalJoint(itemNumbers=[rod, slider], position=q)
    guide = mbs.CreatePrismaticJoint(itemNumbers=[ground, slider], position=q, axis=k4, useGlobalFrame=True)

    bodies = {"crank": (crank, m1, np.diag(i1)), "rod": (rod, m2, np.diag(i2)), "slider": (slider, m3, np.zeros((3, 3)))}
    read = ("Position", "Acceleration", "AngularVelocity", "AngularAcceleration", "RotationMatrix")
    sensors = {(name, what): mbs.AddSensor(SensorBody(bodyNumber=body, storeInternal=True,
                                                      outputVariableType=getattr(exu.OutputVariableType, what)))
               for name, (body, _, _) in bodies.items() for what in read}
    sensors["drive"] = mbs.AddSensor(SensorObject(objectNumber=drive, storeInternal=True,
                                                  outputVariableType=exu.OutputVariableType.Force))
    for joint in (bearing, guide):
        sensors[joint] = mbs.AddSensor(SensorObject(objectNumber=joint, storeInternal=True,
                                                    outputVariableType=exu.OutputVariableType.ForceLocal))
    mbs.Assemble()

    step = np.radians(step_deg) / omega
    steps = int(round(revolutions(step_deg) * 360.0 / step_deg))
    settings = exu.SimulationSettings()
    settings.timeIntegration.numberOfSteps = steps
    settings.timeIntegration.endTime = steps * step
    settings.timeIntegration.newton.useModifiedNewton = False
    settings.timeIntegration.newton.relativeTolerance = solver.newton_tolerance
    settings.timeIntegration.newton.absoluteTolerance = solver.newton_tolerance
    settings.timeIntegration.generalizedAlpha.spectralRadius = solver.spectral_radius
    settings.timeIntegration.generalizedAlpha.computeInitialAccelerations = True
    settings.timeIntegration.verboseMode = 0
    settings.solution.file.write = False
    settings.solution.sensors.writePeriod = step
    settings.show.statistics = False
    settings.show.computationTime = False
    if not mbs.SolveDynamic(settings):
        raise RuntimeError(f"Exudyn's time integration failed (crank pin {crank_pin}, step {step_deg} deg)")

    def stored(key):
        return mbs.GetSensorStoredData(sensors[key])[:, 1:]

    force, moment = 0.0, 0.0
    for name, (_, mass, inertia) in bodies.items():
        r, a, w, alpha = (stored((name, what)) for what in read[:4])
        rot = stored((name, "RotationMatrix")).reshape(-1, 3, 3)
        i_global = np.einsum("nij,jk,nlk->nil", rot, inertia, rot)
        force = force + mass * a
        moment = moment + mass * np.cross(r, a) + np.einsum("nij,nj->ni", i_global, alpha) \
            + np.cross(w, np.einsum("nij,nj->ni", i_global, w))
    # the ground joints' reactions, each in its ground marker's frame (ForceLocal)
    reactions = sum(stored(j) @ np.asarray(mbs.GetMarker(mbs.GetObject(j)["markerNumbers"][0])["localHT"])[:3, :3].T
                    for j in (bearing, guide))
    last = slice(steps - int(round(360.0 / step_deg)), steps + 1)
    rows = np.arange(len(CRANK_DEG)) * int(round(10.0 / step_deg)) + last.start
    return pd.DataFrame({"crank_deg": CRANK_DEG, "5_3": np.linalg.norm(force[rows], axis=1),
                         "5_4": np.linalg.norm(moment[rows], axis=1), "5_7": -stored("drive")[rows, 0],
                         "ground_residual": np.abs(force + reactions)[last].max()})


def port_columns(inputs: CsspInputs = CsspInputs()) -> tuple[dict[str, pd.DataFrame], dict[str, np.ndarray]]:
    """The corrected port's 'before' and 'after' columns of Tables 5.3, 5.4, 5.7 at the 37
    angles (by ``MASSES``), and the point masses behind each (the 'after' ones: the QP's)."""
    run = balance(inputs, quirks=CSSP_CORRECTED)
    columns = {kind: pd.DataFrame({"crank_deg": CRANK_DEG,
                                   **{t: run["table"][:, col + shift] for t, _, _, col in QUANTITIES}})
               for shift, kind in enumerate(MASSES)}
    return columns, {"before": Constants.of(inputs, real4=False).point_masses, "after": run["solution"]}


def agreement(port: pd.DataFrame, exudyn: pd.DataFrame) -> dict[str, tuple[float, float]]:
    """Per table: (the port column's peak |value|, the largest |Exudyn - port|)."""
    return {t: (float(np.abs(port[t]).max()), float(np.abs(exudyn[t] - port[t]).max())) for t, _, _, _ in QUANTITIES}


def run(out_dir: Path) -> pd.DataFrame:
    """out/rahman1996-multibody/: curves.csv (every angle, masses, crank pin: port, Exudyn),
    agreement.csv (peaks and largest differences), report.md."""
    multibody.require()
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    port, masses = port_columns()
    curves, rows = [], []
    for kind in MASSES:
        for pin in JOINTS:
            progress.note(NAME, f"{kind} masses, {pin} crank pin")
            begin = time.perf_counter()
            ex = simulate(masses[kind], pin)
            seconds = time.perf_counter() - begin
            curves += [pd.DataFrame({"masses": kind, "crank_pin": pin, "table": t, "crank_deg": CRANK_DEG,
                                     "port": port[kind][t], "exudyn": ex[t]}) for t, _, _, _ in QUANTITIES]
            rows += [{"masses": kind, "crank_pin": pin, "table": t, "peak": peak, "max_difference": diff,
                      "relative": diff / peak, "ground_residual": ex["ground_residual"].iloc[0],
                      "exudyn_seconds": seconds} for t, (peak, diff) in agreement(port[kind], ex).items()]
    table = pd.DataFrame(rows)
    write_csv(pd.concat(curves, ignore_index=True), target / "curves.csv", FULL_PRECISION)
    write_csv(table, target / "agreement.csv", FULL_PRECISION)
    (target / "report.md").write_text(report(table))
    return table


def report(table: pd.DataFrame) -> str:
    """report.md: the model, its step and revolutions, the agreement per masses, crank pin and table."""
    names = {t: f"{quantity} (Table {t.replace('_', '.')}, {unit})" for t, quantity, unit, _ in QUANTITIES}
    lines = [f"# {TITLE}", "", __doc__.split("\n\n", 1)[1].rsplit("\n\nUnits", 1)[0].strip(), "",
             f"Exudyn {multibody.version()}, a step of {STEP_DEG:g} deg of crank, {_revolutions_words(STEP_DEG)} "
             "compared at the 37 table angles.  The step is chosen by `linkrepro bench`'s knob \"Exudyn step (CSSP)\" "
             f"(its steps {', '.join(f'{s:g}' for s in STEPS)} deg, the 'before' masses, the universal crank pin): "
             "the largest difference falls as h^2 to about 1e-6 of the peaks at this step, to a round-off floor below.", "",
             "| masses | crank pin | quantity | peak | largest difference | of the peak |", "|---|---|---|---|---|---|"]
    lines += [f"| {r.masses} | {r.crank_pin} | {names[r.table]} | {r.peak:.6g} | {r.max_difference:.3g} | "
              f"{r.relative:.2g} |" for r in table.itertuples()]
    residual = table["ground_residual"].max()
    lines += ["", f"Newton's law by Exudyn's own constraint forces: |sum of m a + ground reactions| at most "
              f"{residual:.2g} lbf over the compared revolution.", "",
              "The 1996 thesis gives no stiffness of its links (no modulus, section or material), "
              "so its rigid-body assumption cannot be checked the way Ali's (1977) is.", ""]
    return "\n".join(lines)


def _revolutions_words(step_deg: float) -> str:
    """How ``simulate`` runs at ``step_deg``, in words for the report."""
    if revolutions(step_deg) == 1:
        return ("one revolution from the port's state at 0 deg (the solver's start-up dies out within the "
                f"{int(round(10.0 / step_deg))} steps to the first table angle after 0 deg)")
    return f"the last of {revolutions(step_deg)} revolutions from the port's state at 0 deg"


def overview(table: pd.DataFrame) -> list[str]:
    lines = []
    for (kind, pin), g in table.groupby(["masses", "crank_pin"], sort=False):
        lines.append(f"{kind} masses, {pin} crank pin: Exudyn within "
                     + ", ".join(f"{r.relative:.1e}" for r in g.itertuples())
                     + " of the peaks of Tables 5.3, 5.4, 5.7")
    return lines


SCENE = ReportScene(name=NAME, title=TITLE, group=NAME, start=4, produce=run, overview=overview)
