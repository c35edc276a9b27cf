"""One module per figure of the paper: analyze(summary, out_dir) -> result (a dict with the
figure's name, the paper's value, ours with its bootstrap interval, and the plot's path),
from the runs' own files (study_io). analyze.py picks the module by the study's name."""
