#ifndef ROPRAS_OMPL_EXT_MESH_LOADER_H
#define ROPRAS_OMPL_EXT_MESH_LOADER_H

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief A triangle mesh in its own frame, scale already applied. */
    struct TriangleMesh
    {
        std::vector<Eigen::Vector3d> vertices;
        std::vector<Eigen::Vector3i> triangles;
    };

    /** \brief Load a mesh with assimp (OBJ, STL, DAE, ...), all sub-meshes merged, \a scale applied.
        Throws ropras::Error naming the file if it is missing, unreadable or has no triangles. */
    TriangleMesh loadMesh(const std::string &path, const Eigen::Vector3d &scale = Eigen::Vector3d::Ones());

    /** \brief Resolve a URDF mesh filename: `package://pkg/rest` and relative paths are looked up against
        \a baseDir (the URDF's folder) and its parents; `file://` and absolute paths are taken as they are.
        Throws ropras::Error naming \a urdfSource and the filename when nothing exists. */
    std::string resolveMeshPath(const std::string &filename, const std::string &baseDir, const std::string &urdfSource);
}  // namespace ropras::ompl_ext

#endif
