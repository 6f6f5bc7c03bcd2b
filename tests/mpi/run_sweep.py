"""A sweep case through wearscale.run() (tests/mpi/test_mpi_python_run.cpp): run as
``python3 run_sweep.py CASE OUT`` and as ``mpirun -np N python3 run_sweep.py CASE OUT``, where
the C++ side owns MPI (no mpi4py): the runs are farmed over the ranks and rank 0 writes."""
import sys

import wearscale
from wearscale import _wearscale

case, out = sys.argv[1], sys.argv[2]
result = wearscale.run(case, out=out, scale__macro__grid=32, scale__macro__distance=0.05,
                       run__fft_planning="estimate")
rank, size = _wearscale.mpi.rank(), _wearscale.mpi.size()
if rank == 0:
    # Rank 0 speaks for the job; its result is the whole sweep's.
    print(f"ranks {size}: {result['output_dir']}")
