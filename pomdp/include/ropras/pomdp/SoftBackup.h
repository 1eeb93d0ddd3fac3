#ifndef ROPRAS_POMDP_SOFT_BACKUP_H
#define ROPRAS_POMDP_SOFT_BACKUP_H

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace ropras::pomdp
{
    /** \brief log(exp(x) + exp(y)) without overflow; either argument may be -infinity. */
    inline double logAddExp(double x, double y) noexcept
    {
        if (x < y)
        {
            const double t = x;
            x = y;
            y = t;
        }
        if (y == -std::numeric_limits<double>::infinity())
        {
            return x;
        }
        return x + std::log1p(std::exp(y - x));
    }

    /** \brief The reference-based value backup of ROP-RAS3 (Algorithm 2, Backup lines 4-5).

        \a v is the current V(b) (ignored when \a n == 1), \a q the freshly updated Q(b, a) of the action
        chosen in this simulation, \a n = N(b) after the increment. Returns
        V <- (1/eta) log[ exp(eta V) + (exp(eta Q) - exp(eta V)) / N ]
        in log space (exp(eta V) is the running
        mean of exp(eta Q) and never overflows (rewards of +-800 with eta = 0.2 are fine): it is evaluated
        as eta V + log1p(expm1(eta (Q - V)) / N), or, when eta (Q - V) > 50, as
        eta Q - log N + log1p((N - 1) exp(eta (V - Q))). */
    inline double softValueUpdate(double v, double q, std::size_t n, double eta) noexcept
    {
        if (n <= 1)
        {
            return q;
        }
        const double dn = static_cast<double>(n);
        const double w = eta * v;
        const double d = eta * q - w;
        if (d <= 50.0)
        {
            // eta V' = eta V + log(1 + (exp(eta Q - eta V) - 1) / N); the argument of log1p is > -1/N.
            return (w + std::log1p(std::expm1(d) / dn)) / eta;
        }
        // Q far above V: eta V' = eta Q - log N + log(1 + (N - 1) exp(eta V - eta Q)).
        return (eta * q - std::log(dn) + std::log1p((dn - 1.0) * std::exp(-d))) / eta;
    }

    /** \brief Batch form of Theorem 1 over \a count entries: (1/eta) log sum_i w_i exp(eta q_i) / sum_i w_i
        (log-sum-exp; entries of weight 0 are skipped). \a entry(i) returns the pair (q_i, w_i), so a caller can
        read them from its own storage (a search node's children) without copying. Returns -infinity when all
        weights are 0 or count is 0. */
    template <class Entry>
    double softValueOf(std::size_t count, Entry &&entry, double eta) noexcept
    {
        double best = -std::numeric_limits<double>::infinity();
        double totalWeight = 0.0;
        for (std::size_t i = 0; i < count; ++i)
        {
            const auto [q, w] = entry(i);
            if (w > 0.0 && eta * q > best)
            {
                best = eta * q;
            }
            totalWeight += w;
        }
        if (!(totalWeight > 0.0) || best == -std::numeric_limits<double>::infinity())
        {
            return -std::numeric_limits<double>::infinity();
        }
        double sum = 0.0;
        for (std::size_t i = 0; i < count; ++i)
        {
            const auto [q, w] = entry(i);
            if (w > 0.0)
            {
                sum += w * std::exp(eta * q - best);
            }
        }
        return (best + std::log(sum / totalWeight)) / eta;
    }

    /** \brief softValueOf() over arrays: q[i] with weights w[i] (\a w null: every weight 1). */
    inline double softValue(const double *q, const double *w, std::size_t count, double eta) noexcept
    {
        return softValueOf(
            count, [q, w](std::size_t i) { return std::pair<double, double>(q[i], w ? w[i] : 1.0); }, eta);
    }
}  // namespace ropras::pomdp

#endif
