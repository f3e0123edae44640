# R bnlearn's side of bench/peers/hc_vs_bnlearn.py (not part of pgm; R_LIBS names where
# cmake/peers.cmake installed bnlearn).
#   Rscript bnlearn_hc.R sample <network.bif> <rows> <seed> <out.csv>    rbn() sample, written as CSV
#   Rscript bnlearn_hc.R compare <network.bif> <data.csv> <algorithm> <pgm_arcs.csv>
# compare prints: bnlearn's seconds (the hc()/tabu() call alone), BIC and CPDAG SHD to the truth,
# then the BIC and SHD of pgm's arcs on the same data.
suppressMessages(library(bnlearn))
args = commandArgs(TRUE)
net = read.bif(args[2])
if (args[1] == "sample") {
  set.seed(as.integer(args[4]))
  d = rbn(net, n = as.integer(args[3]))
  write.csv(d, args[5], row.names = FALSE, quote = FALSE)
} else {
  d = droplevels(read.csv(args[3], colClasses = "factor"))
  truth = cpdag(bn.net(net))
  alg = args[4]
  seconds = system.time(g <- if (alg == "tabu") tabu(d, score = "bic") else hc(d, score = "bic"))[["elapsed"]]
  a = read.csv(args[5], colClasses = "character")
  ours = empty.graph(names(d))
  if (nrow(a) > 0) arcs(ours) = as.matrix(a)
  cat(seconds, sprintf("%.17g", score(g, d, type = "bic")), shd(cpdag(g), truth),
      sprintf("%.17g", score(ours, d, type = "bic")), shd(cpdag(ours), truth), "\n")
}
