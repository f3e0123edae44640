# R bnlearn's answers for tests/peers/bnlearn_agreement_test.cpp (not part of pgm; run with
# R_LIBS naming where cmake/peers.cmake installed bnlearn from ../shared/peers).
#   Rscript bnlearn_oracle.R <network.bif> <data.csv> <output.txt>
# Writes one line per answer, values with 17 significant digits:
#   score <type> <iss> <total> <node term>...   score() of the network's DAG, the data read with
#                                                the network's states (unseen ones included)
#   hc <bic> <seconds>                           hc(score = "bic") on the data with the states seen
#   arc <from> <to>                              hc()'s arcs
#   tabu <bic>                                   tabu(score = "bic")
suppressMessages(library(bnlearn))
args = commandArgs(TRUE)
net = read.bif(args[1])
data = read.csv(args[2], colClasses = "character", check.names = FALSE)
full = data
for (v in names(net)) full[[v]] = factor(data[[v]], levels = dimnames(net[[v]]$prob)[[1]])
full = full[, names(net)]
dag = bn.net(net)
out = file(args[3], "w")
num = function(x) sprintf("%.17g", x)
for (request in list(list("loglik", 1), list("aic", 1), list("bic", 1), list("bde", 1), list("bde", 10),
                     list("k2", 1))) {
  type = request[[1]]
  iss = request[[2]]
  terms = if (type == "bde") score(dag, full, type = type, iss = iss, by.node = TRUE) else
    score(dag, full, type = type, by.node = TRUE)
  writeLines(paste("score", type, iss, num(sum(terms)), paste(num(terms[names(net)]), collapse = " ")), out)
}
seen = droplevels(full)
seconds = system.time(learned <- hc(seen, score = "bic"))[["elapsed"]]
writeLines(paste("hc", num(score(learned, seen, type = "bic")), seconds), out)
a = arcs(learned)
for (k in seq_len(nrow(a))) writeLines(paste("arc", a[k, 1], a[k, 2]), out)
searched = tabu(seen, score = "bic")
writeLines(paste("tabu", num(score(searched, seen, type = "bic"))), out)
close(out)
