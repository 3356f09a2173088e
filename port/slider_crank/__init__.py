"""The spatial slider-crank loop that both Rahman theses solve (1991: the method; 1996: its
listing): :mod:`.geometry` (the inputs, the loop's constants, the printed first estimate),
:mod:`._newton` (private: the compiled dual-number Newton-Raphson of the loop closure
M1 L2 L3 M4 = I and its rates, kernels on bare numbers for ``rahman1996.listing`` and
``rahman1991.position``) and :mod:`.kinematics` (the exact closed-loop kinematics, second-order
jets).
"""
