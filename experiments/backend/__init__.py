"""The one place where every study's points are run: a point list (one point per line, the file
that marks it done and its command) goes to GNU parallel on this machine, GNU parallel over ssh,
or a Slurm job array, and comes back as the same list of what is done and what failed."""
