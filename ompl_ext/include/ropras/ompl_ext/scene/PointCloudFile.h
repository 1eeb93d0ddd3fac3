#ifndef ROPRAS_OMPL_EXT_POINT_CLOUD_FILE_H
#define ROPRAS_OMPL_EXT_POINT_CLOUD_FILE_H

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief Options of loadPointCloudFile(). */
    struct PointCloudFileOptions
    {
        /// drop NaN / infinite points (organized clouds mark missing returns with NaN) instead of refusing the file
        bool dropNonFinite{false};
    };

    /** \brief The x, y, z of every point of a point cloud file, in the file's frame: PCD (PCL's format, DATA ascii
        or binary; binary_compressed is refused) or PLY (ascii, binary_little_endian, binary_big_endian; the
        `vertex` element's x, y, z), chosen by the extension (.pcd / .ply, any case). Other fields and elements
        are skipped. Throws ropras::Error naming the file and the problem: missing, special or oversized file
        (core/InputFile.h), malformed header, a count the data does not hold, a truncated or malformed value,
        trailing data, a NaN or infinite point (unless dropped; the message names its index). */
    std::vector<Eigen::Vector3f> loadPointCloudFile(const std::string &path,
                                                    const PointCloudFileOptions &options = PointCloudFileOptions());
}  // namespace ropras::ompl_ext

#endif
