// Fisher's exact test on a 2x2 table, two-sided: compares two groups' success
// counts with the trials pooled (comparison reports).
#pragma once

namespace corrmp {

// The table
//   | a  b |   e.g. group A: a successes, b failures
//   | c  d |        group B: c successes, d failures
// Two-sided p-value: the probability, under the hypergeometric distribution
// of the table with its margins fixed, of every table no more probable than
// the observed one (with a relative tolerance of 1e-7, as R's fisher.test).
double fisher_exact_two_sided(int a, int b, int c, int d);

}  // namespace corrmp
