/*
  Private inline Gaussian generator of the simulator's sensor noise: the same sequence of doubles, bit for bit, as
  ViSP's vpGaussRand(sigma, mean, seed), whose draws are out-of-line library calls (vpGaussRand::gaussianDraw(),
  vpUniRand::uniform(), vpUniRand::next()) three times per pixel of every simulated frame.

  The algorithm vpGaussRand implements (ViSP 3.5): a PCG32 generator (XSH-RR output of a 64-bit LCG) seeded with
  (seed, stream 0x123465789); uniforms next() / (2^32 - 1) in [0, 1]; Marsaglia's polar method, which turns each
  pair of uniforms inside the unit disc into two normal deviates, the second kept for the next call; the result
  scaled as sigma * deviate + mean. Every floating-point operation here is the one vpGaussRand performs, in the same
  order, and std::log / std::sqrt are the same libm calls, so the results are identical; test_sim_exact compares
  millions of draws of both for several seeds and (sigma, mean) pairs. The uniform's "* (b - a) + a" with a = 0,
  b = 1 is left out: x * 1 and x + 0 are exact for the x >= 0 it multiplies.

  A build that lets the compiler contract a * b + c into a fused multiply-add (an FMA target with
  -ffp-contract=fast) would round differently from the distributed library; test_sim_exact would then fail.
*/
#ifndef VP_SSL_GAUSS_RAND_H
#define VP_SSL_GAUSS_RAND_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "vpSSLNoiseKernel.h"

//! Gaussian deviates identical to those of vpGaussRand(sigma, mean, seed), with inline draws.
class vpSSLGaussRand
{
public:
  //! The generator of vpGaussRand(sigma, mean, seed): standard deviation, mean, seed.
  vpSSLGaussRand(double sigma, double mean, long seed)
      : m_state(0), m_inc((kStream << 1u) | 1u), m_sigma(sigma), m_mean(mean), m_hasSecond(false), m_second(0.)
  {
    // vpUniRand::setSeed(seed, stream): a step from state 0, the seed added, a second step.
    next();
    m_state += static_cast<uint64_t>(seed);
    next();
  }

  //! The next deviate, sigma * N(0, 1) + mean, as vpGaussRand::operator()().
  double operator()() { return m_sigma * standardDraw() + m_mean; }

  /*!
    The next \e count deviates, those of \e count calls of operator()() in their order, into \e out; the generator
    is left where those calls leave it. The polar method's candidate pairs are drawn ahead, the accepted ones kept
    without a branch on the random outcome, and their logarithms, divisions and square roots done in loops of their
    own (vpSSLNoiseKernel); the draws past the last pair used are taken back.
  */
  void draw(double *out, size_t count)
  {
    size_t k = 0;
    if (count > 0 && m_hasSecond) {
      m_hasSecond = false;
      out[k++] = m_sigma * m_second + m_mean;
    }
    double v1[kCandidates], v2[kCandidates], rsq[kCandidates], logRsq[kCandidates], fac[kCandidates];
    uint64_t stateAfter[kCandidates];
    while (k < count) {
      const size_t pairs = (count - k + 1) / 2;
      // A pair is accepted with probability pi / 4: a third more candidates than pairs needed, most often enough.
      const size_t nc = std::min(kCandidates, pairs + pairs / 3 + 4);
      size_t na = 0;
      for (size_t i = 0; i < nc; ++i) {
        const double a = 2. * uniform() - 1.;
        const double b = 2. * uniform() - 1.;
        const double r = a * a + b * b;
        v1[na] = a;
        v2[na] = b;
        rsq[na] = r;
        stateAfter[na] = m_state;
        na += r < 1. ? 1 : 0;
      }
      const size_t used = std::min(na, pairs);
      if (used > 0) {
        m_state = stateAfter[used - 1];
      }
      for (size_t i = 0; i < used; ++i) {
        logRsq[i] = std::log(rsq[i]);
      }
      vpSSLNoiseKernel::polarFactors(rsq, logRsq, used, fac);
      for (size_t i = 0; i < used; ++i) {
        out[k++] = m_sigma * (v1[i] * fac[i]) + m_mean;
        if (k < count) {
          out[k++] = m_sigma * (v2[i] * fac[i]) + m_mean;
        } else {
          m_second = v2[i] * fac[i];
          m_hasSecond = true;
        }
      }
    }
  }

private:
  //! Candidate pairs drawn ahead at most, per pass of draw().
  static constexpr size_t kCandidates = 512;

  //! The PCG32 stream vpGaussRand's vpUniRand is seeded on.
  static constexpr uint64_t kStream = 0x123465789ULL;

  //! PCG32: 64-bit LCG step, 32-bit output by xorshift and a random rotation.
  uint32_t next()
  {
    const uint64_t old = m_state;
    m_state = old * 6364136223846793005ULL + m_inc;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
  }

  //! Uniform in [0, 1]: next() / (2^32 - 1), as the product vpUniRand computes.
  double uniform() { return next() * (1.0 / static_cast<double>(UINT32_MAX)); }

  //! N(0, 1) by Marsaglia's polar method, two deviates per accepted pair.
  double standardDraw()
  {
    if (m_hasSecond) {
      m_hasSecond = false;
      return m_second;
    }
    double v1 = 0., v2 = 0., rsq = 0.;
    do {
      v1 = 2. * uniform() - 1.;
      v2 = 2. * uniform() - 1.;
      rsq = v1 * v1 + v2 * v2;
    } while (rsq >= 1.);
    const double fac = std::sqrt(-2. * std::log(rsq) / rsq);
    m_second = v2 * fac;
    m_hasSecond = true;
    return v1 * fac;
  }

  uint64_t m_state; //!< LCG state.
  uint64_t m_inc;   //!< LCG increment (odd): the stream.
  double m_sigma;   //!< Standard deviation.
  double m_mean;    //!< Mean.
  bool m_hasSecond; //!< The second deviate of the last pair is still to be returned.
  double m_second;  //!< That deviate.
};

#endif
