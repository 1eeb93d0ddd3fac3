// Forward kinematics of a batch (one configuration per lane) for any 8-lane backend V.
#ifndef ROPRAS_OMPL_EXT_SIMD_BATCH_FRAMES_H
#define ROPRAS_OMPL_EXT_SIMD_BATCH_FRAMES_H

#include "ForceInline.h"
#include "KinematicProgram.h"
#include "Placed.h"
#include "SinCos.h"

namespace ropras::ompl_ext::simd
{
    /** \brief Forward kinematics of WIDTH configurations, one per lane: frames, link bounds and, on demand,
        the spheres of a link. */
    template <class V>
    struct BatchFrames
    {
        /// the rotation columns of m (rows r00 r01 r02, r10 ...) reordered in place: new column j = old column Cj
        template <int C0, int C1, int C2>
        static void permuteColumns(V *m) noexcept
        {
            for (int i = 0; i < 3; ++i)
            {
                const V a = m[3 * i + C0], b = m[3 * i + C1], c = m[3 * i + C2];
                m[3 * i] = a;
                m[3 * i + 1] = b;
                m[3 * i + 2] = c;
            }
        }

        /** \brief m = m * offset (12-float transforms, WIDTH lanes each) in place. The translation goes first (it
            uses m's rotation) and only for the offset's non-zero components; a signed-permutation rotation is
            column moves and sign-bit XORs of the flipped columns; any other rotation is three FMAs per entry,
            row by row (three live values, not a second matrix). */
        static void applyOffset(const FrameOp &op, V *m) noexcept
        {
            const float *o = op.offset;
            for (int k = 0; k < 3; ++k)
                if ((op.translationMask >> k) & 1u)
                {
                    const V ok = V::broadcast(o[9 + k]);
                    for (int i = 0; i < 3; ++i)
                        m[9 + i] = fma(m[3 * i + k], ok, m[9 + i]);
                }
            if (op.permutation)
            {
                switch (op.permId)
                {
                    case 0:
                        break;
                    case 1:
                        permuteColumns<0, 2, 1>(m);
                        break;
                    case 2:
                        permuteColumns<1, 0, 2>(m);
                        break;
                    case 3:
                        permuteColumns<1, 2, 0>(m);
                        break;
                    case 4:
                        permuteColumns<2, 0, 1>(m);
                        break;
                    default:
                        permuteColumns<2, 1, 0>(m);
                        break;
                }
                for (int j = 0; j < 3; ++j)
                    if ((op.flipColumns >> j) & 1u)
                    {
                        const V sg = V::broadcast(-0.0f);
                        for (int i = 0; i < 3; ++i)
                            m[3 * i + j] = flipSign(m[3 * i + j], sg);
                    }
                return;
            }
            for (int i = 0; i < 3; ++i)
            {
                const V a = m[3 * i], b = m[3 * i + 1], c = m[3 * i + 2];
                for (int j = 0; j < 3; ++j)
                    m[3 * i + j] =
                        fma(a, V::broadcast(o[j]), fma(b, V::broadcast(o[3 + j]), c * V::broadcast(o[6 + j])));
            }
        }

        /** \brief FK of WIDTH configurations: per variable joint values in buf + batch.q (WIDTH floats each,
            angles already reduced); writes frames and link bounds (WIDTH floats each). Spheres: placeLinkBatch.
            One frame lives in registers and is updated in place (a frame whose parent is the previous frame does
            not reload it); the offset is applied with only the work its form needs (applyOffset); each frame's
            link bounds are placed while it is in registers. */
        static void framesBatch(const KinematicProgram &p, float *buf) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            for (int j = 0; j < p.dof; ++j)
                if (p.rotational[static_cast<std::size_t>(j)])
                {
                    V s, c;
                    sinCos(V::load(buf + l.q + W * j), s, c);
                    s.store(buf + l.sin + W * j);
                    c.store(buf + l.cos + W * j);
                }
            float *t = buf + l.frames;
            float *lx = buf + l.lx, *ly = buf + l.ly, *lz = buf + l.lz;
            // the program's arrays in locals: the stores below may alias anything (members would be reloaded)
            const FrameOp *frames = p.frames.data();
            const LinkOp *links = p.links.data();
            const int *frameLinks = p.frameLinks.data();
            const int nFrames = static_cast<int>(p.frames.size());
            if (nFrames == 0)
                return;
            // frame 0 has no parent (compileProgram checks it): m starts as its offset, set again in the loop
            // (a zero fill here was a call to memset)
            V m[12];
            for (int i = 0; i < 12; ++i)
                m[i] = V::broadcast(frames[0].offset[i]);
            for (int f = 0; f < nFrames; ++f)
            {
                const FrameOp &op = frames[f];
                float *tf = t + 12 * W * f;
                if (op.parent < 0)
                {
                    for (int i = 0; i < 12; ++i)
                        m[i] = V::broadcast(op.offset[i]);
                }
                else
                {
                    if (op.parent != f - 1)
                    {
                        const float *pt = t + 12 * W * op.parent;
                        for (int i = 0; i < 12; ++i)
                            m[i] = V::load(pt + W * i);
                    }
                    applyOffset(op, m);
                }
                if (op.motion == Motion::RotateZ)
                {
                    const V c = V::load(buf + l.cos + W * op.variable), s = V::load(buf + l.sin + W * op.variable);
                    for (int i = 0; i < 3; ++i)
                    {
                        const V a = m[3 * i], b = m[3 * i + 1];
                        m[3 * i] = fma(c, a, s * b);
                        m[3 * i + 1] = fnma(s, a, c * b);
                    }
                }
                else if (op.motion == Motion::TranslateZ)
                {
                    const V d = V::load(buf + l.q + W * op.variable);
                    for (int i = 0; i < 3; ++i)
                        m[9 + i] = fma(d, m[3 * i + 2], m[9 + i]);
                }
                for (int i = 0; i < 12; ++i)
                    m[i].store(tf + W * i);
                for (int k = op.linkBegin; k < op.linkEnd; ++k)
                {
                    const int li = frameLinks[k];
                    const LinkOp &link = links[li];
                    const V vx = V::broadcast(link.bx), vy = V::broadcast(link.by), vz = V::broadcast(link.bz);
                    fma(m[0], vx, fma(m[1], vy, fma(m[2], vz, m[9]))).store(lx + W * li);
                    fma(m[3], vx, fma(m[4], vy, fma(m[5], vz, m[10]))).store(ly + W * li);
                    fma(m[6], vx, fma(m[7], vy, fma(m[8], vz, m[11]))).store(lz + W * li);
                }
            }
        }

        /// world position (WIDTH lanes per axis) of the point \a b (3 floats, in the frame stored at \a frame)
        static void placePointBatch(const float *frame, const float *b, V *out) noexcept
        {
            constexpr int W = WIDTH;
            const V vx = V::broadcast(b[0]), vy = V::broadcast(b[1]), vz = V::broadcast(b[2]);
            for (int i = 0; i < 3; ++i)
                out[i] = fma(V::load(frame + W * (3 * i)), vx,
                             fma(V::load(frame + W * (3 * i + 1)), vy,
                                 fma(V::load(frame + W * (3 * i + 2)), vz, V::load(frame + W * (9 + i)))));
        }

        /** \brief A batch frame (12 values, WIDTH lanes each) in named registers. An array filled in a loop became a
            call to memcpy into the stack (384 bytes per link, 12 % of the batch FK's instructions) and loads back. */
        struct FrameRegisters
        {
            V r00, r01, r02, r10, r11, r12, r20, r21, r22, tx, ty, tz;

            static FrameRegisters load(const float *pt) noexcept
            {
                constexpr int W = WIDTH;
                return {V::load(pt),         V::load(pt + W),     V::load(pt + 2 * W),  V::load(pt + 3 * W),
                        V::load(pt + 4 * W), V::load(pt + 5 * W), V::load(pt + 6 * W),  V::load(pt + 7 * W),
                        V::load(pt + 8 * W), V::load(pt + 9 * W), V::load(pt + 10 * W), V::load(pt + 11 * W)};
            }

            /// the world position of the frame point (x, y, z) into \a wx, \a wy, \a wz (WIDTH floats each)
            void place(float x, float y, float z, float *wx, float *wy, float *wz) const noexcept
            {
                const V vx = V::broadcast(x), vy = V::broadcast(y), vz = V::broadcast(z);
                fma(r00, vx, fma(r01, vy, fma(r02, vz, tx))).store(wx);
                fma(r10, vx, fma(r11, vy, fma(r12, vz, ty))).store(wy);
                fma(r20, vx, fma(r21, vy, fma(r22, vz, tz))).store(wz);
            }
        };

        /// world centres (WIDTH lanes each) of one link's real spheres
        static void placeLinkBatch(const KinematicProgram &p, float *buf, int li) noexcept
        {
            const ScratchLayout &l = p.batch;
            constexpr int W = WIDTH;
            const LinkOp &link = p.links[static_cast<std::size_t>(li)];
            const FrameRegisters m = FrameRegisters::load(buf + l.frames + 12 * W * link.frame);
            // everything the loop reads through p in locals: vector stores may alias anything, so members read
            // in the loop would be reloaded after every store
            const float *px = p.sx.data(), *py = p.sy.data(), *pz = p.sz.data();
            float *wx = buf + l.sx, *wy = buf + l.sy, *wz = buf + l.sz;
            const int first = link.first, end = link.first + link.count;
            for (int s = first; s < end; ++s)
                m.place(px[s], py[s], pz[s], wx + W * s, wy + W * s, wz + W * s);
        }

        /** \brief After framesBatch: the world centre and radius of every RobotModel sphere straight into \a out
            (per sphere x, y, z, r, WIDTH lanes each, in RobotModel order), not through the scratch spheres. */
        static void sphereCentersBatch(const KinematicProgram &p, const float *buf, float *out) noexcept
        {
            constexpr int W = WIDTH;
            const float *px = p.sx.data(), *py = p.sy.data(), *pz = p.sz.data(), *pr = p.sr.data();
            const int *sphereOfSlot = p.sphereOfSlot.data();
            for (const LinkOp &link : p.links)
            {
                const FrameRegisters m = FrameRegisters::load(buf + p.batch.frames + 12 * W * link.frame);
                for (int s = link.first; s < link.first + link.count; ++s)
                {
                    float *o = out + 4 * W * static_cast<std::size_t>(sphereOfSlot[s]);
                    m.place(px[s], py[s], pz[s], o, o + W, o + 2 * W);
                    V::broadcast(pr[s]).store(o + 3 * W);
                }
            }
        }

        ROPRAS_SIMD_FORCE_INLINE static void ensureBatch(const KinematicProgram &p, float *buf, Placed &placed,
                                                         int li) noexcept
        {
            if (!placed.has(li))
            {
                placeLinkBatch(p, buf, li);
                placed.set(li);
            }
        }

        static void placeAllBatch(const KinematicProgram &p, float *buf, Placed &placed) noexcept
        {
            for (int li = 0; li < static_cast<int>(p.links.size()); ++li)
                placeLinkBatch(p, buf, li);
            placed.all = true;
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
