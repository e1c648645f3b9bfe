"""benchlib - the benchmark driver's modules (scripts/bench.py is the command).

methods   the one list of methods (scripts/methods.tsv) and the method key
profiles  the plans of the profiles (smoke, default, paper, seeds, lowk, density) and the cost model
stats     medians, means, id ranges and number formats shared by the tables
runner    `bench.py run`: the plan, the scheduler, runs.csv, quality.csv, spectra.csv
plotdata  `bench.py replot`: the figures' data files and gnuplot
ttq       the time-to-quality runs' table and figure data
density   the density part: every method that takes --density on the test densities and the image
stipple   the stippling figure's runs and its data
summary   summary.md
core      `bench.py core` (make bench-core)
"""
