"""The 1-D absorbers and the 2-D stochastic sink compared at equal mass and damping.

* :func:`~sinktheory.compare.efficiency.compare` -- efficiency (fraction of an impulse's
  energy dissipated in a window) and 90 % time against the initial energy, with standard
  errors over seeded runs (:class:`~sinktheory.compare.efficiency.Comparison`);
* :func:`~sinktheory.compare.efficiency.attachments_of` -- the attachments of a list of
  kinds (``nes``, ``impact``, ``well``) at one total mass;
* :func:`~sinktheory.compare.transfer.transfer_map` -- the Morlet wavelet map of the
  container's displacement after an impulse, its ridge against the energy left, and
  :func:`~sinktheory.compare.transfer.backbone` -- the normal modes' frequency-energy
  curves it is drawn over;
* :func:`~sinktheory.compare.wavelet.wavelet_map` -- the wavelet map of any signal.

The charts are in :mod:`sinktheory.plot.compare`; the command is ``sinktheory compare``.
Modules are loaded on first use.
"""

from importlib import import_module

_LAZY = {
    "Comparison": "efficiency",
    "compare": "efficiency",
    "attachments_of": "efficiency",
    "energies_of": "efficiency",
    "TransferMap": "transfer",
    "transfer_map": "transfer",
    "backbone": "transfer",
    "WaveletMap": "wavelet",
    "wavelet_map": "wavelet",
}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = sorted(_LAZY)
