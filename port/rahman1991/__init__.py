"""Rahman (1991): displacement, velocity, acceleration and joint-force analysis of the
generalized slider crank (GSC), the method behind the 1996 kinematics.

:mod:`.analysis` gives one configuration (``analyse``) or the example's grid (``sweep``);
:mod:`.position` the printed Newton-Raphson (with its DFP fallback), :mod:`.rates` and
:mod:`.printed_rates` the velocities and accelerations, :mod:`.forces` the joint forces,
:mod:`.data` the example's inputs, :mod:`.quirks` the method's bugs (``GSC_PRINTED``,
``GSC_CORRECTED``).
"""
