/*!
  \file vpSSLCorpusRandom.h
  \brief Seeded random numbers of the evaluation corpus, with distributions written out here.
*/
#ifndef VP_SSL_CORPUS_RANDOM_H
#define VP_SSL_CORPUS_RANDOM_H

#include <cmath>
#include <cstdint>
#include <random>

/*!
  \class vpSSLCorpusRandom
  \ingroup group_ssl_bench
  \brief std::mt19937_64 with its distributions written out here, so that a corpus depends on its seed only
  (the standard library's distributions may differ from one implementation to another).
*/
class vpSSLCorpusRandom
{
public:
  //! Generator seeded with \e seed.
  explicit vpSSLCorpusRandom(uint64_t seed) : m_engine(seed) {}

  //! Mixes two numbers into a seed (splitmix64 finaliser): a view's seed from the corpus seed and its index.
  static uint64_t mix(uint64_t a, uint64_t b)
  {
    uint64_t z = a * 0x9E3779B97F4A7C15ULL + b + 0x632BE59BD9B4E019ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  //! Uniform in [0, 1) (53 bits).
  double uniform() { return static_cast<double>(m_engine() >> 11) * (1.0 / 9007199254740992.0); }
  //! Uniform in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  //! Log-uniform in [a, b), a > 0.
  double logUniform(double a, double b) { return a * std::exp(std::log(b / a) * uniform()); }
  //! Integer uniform in [0, n), n > 0.
  int integer(int n) { return static_cast<int>(uniform() * n); }
  //! True with probability \e p.
  bool chance(double p) { return uniform() < p; }
  //! Standard normal (Box-Muller, one value per call).
  double normal()
  {
    const double u1 = 1. - uniform(); // in (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2. * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  //! A fresh 64-bit seed for a sub-generator.
  uint64_t next() { return m_engine(); }

private:
  std::mt19937_64 m_engine;
};

#endif
