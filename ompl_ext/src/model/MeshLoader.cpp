#include "ropras/ompl_ext/model/MeshLoader.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace fs = std::filesystem;

namespace ropras::ompl_ext
{
    namespace
    {
        bool isRegularFile(const fs::path &p)
        {
            std::error_code ec;
            return fs::is_regular_file(p, ec);
        }

        std::string absoluteString(const fs::path &p)
        {
            std::error_code ec;
            fs::path out = fs::weakly_canonical(fs::absolute(p, ec), ec);
            if (ec)
            {
                out = p.lexically_normal();
            }
            return out.string();
        }

        // Collect the node transforms of the assimp scene graph and append every triangle in the root frame.
        void appendNode(const aiScene *scene, const aiNode *node, const aiMatrix4x4 &parent, TriangleMesh &out,
                        const Eigen::Vector3d &scale)
        {
            const aiMatrix4x4 transform = parent * node->mTransformation;
            for (unsigned int m = 0; m < node->mNumMeshes; ++m)
            {
                const aiMesh *mesh = scene->mMeshes[node->mMeshes[m]];
                const int base = static_cast<int>(out.vertices.size());
                for (unsigned int v = 0; v < mesh->mNumVertices; ++v)
                {
                    const aiVector3D p = transform * mesh->mVertices[v];
                    out.vertices.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
                }
                for (unsigned int f = 0; f < mesh->mNumFaces; ++f)
                {
                    const aiFace &face = mesh->mFaces[f];
                    if (face.mNumIndices != 3)
                    {
                        continue;  // points and lines carry no surface
                    }
                    out.triangles.emplace_back(base + static_cast<int>(face.mIndices[0]),
                                               base + static_cast<int>(face.mIndices[1]),
                                               base + static_cast<int>(face.mIndices[2]));
                }
            }
            for (unsigned int c = 0; c < node->mNumChildren; ++c)
            {
                appendNode(scene, node->mChildren[c], transform, out, scale);
            }
        }
    }  // namespace

    TriangleMesh loadMesh(const std::string &path, const Eigen::Vector3d &scale)
    {
        if (!scale.allFinite() || (scale.array() == 0.0).any())
        {
            throw Error("mesh '" + path + "': scale must be finite and non-zero, got (" + std::to_string(scale.x()) +
                        ", " + std::to_string(scale.y()) + ", " + std::to_string(scale.z()) + ")");
        }
        checkInputFile(path, "mesh");  // a regular file within the input size limit
        Assimp::Importer importer;
        // URDF meshes are Z-up as authored: do not let the COLLADA importer rotate Z-up files to Y-up.
        importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
        // Keep the scene graph (node transforms such as DAE up-axis conversion are applied below) and
        // join identical vertices so the spherizer sees a connected surface.
        const aiScene *scene =
            importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
        if (scene == nullptr || scene->mRootNode == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0)
        {
            throw Error("mesh '" + path + "': assimp cannot read it: " + importer.GetErrorString());
        }
        TriangleMesh out;
        appendNode(scene, scene->mRootNode, aiMatrix4x4(), out, scale);
        if (out.triangles.empty())
        {
            throw Error("mesh '" + path + "': contains no triangles");
        }
        for (const Eigen::Vector3d &v : out.vertices)
        {
            if (!v.allFinite())
            {
                throw Error("mesh '" + path + "': has a non-finite vertex");
            }
        }
        return out;
    }

    std::string resolveMeshPath(const std::string &filename, const std::string &baseDir, const std::string &urdfSource)
    {
        if (filename.empty())
        {
            throw Error("URDF '" + urdfSource + "': empty mesh filename");
        }
        std::vector<fs::path> tried;
        auto found = [&](const fs::path &candidate) -> bool
        {
            tried.push_back(candidate);
            return isRegularFile(candidate);
        };

        const std::string filePrefix = "file://";
        const std::string packagePrefix = "package://";
        if (filename.compare(0, filePrefix.size(), filePrefix) == 0)
        {
            const fs::path p = filename.substr(filePrefix.size());
            if (found(p))
            {
                return absoluteString(p);
            }
        }
        else if (fs::path(filename).is_absolute())
        {
            if (found(filename))
            {
                return absoluteString(filename);
            }
        }
        else
        {
            std::string pkg;
            std::string rest = filename;
            const bool isPackage = filename.compare(0, packagePrefix.size(), packagePrefix) == 0;
            if (isPackage)
            {
                const std::string tail = filename.substr(packagePrefix.size());
                const std::size_t slash = tail.find('/');
                if (slash == std::string::npos || slash == 0)
                {
                    throw Error("URDF '" + urdfSource + "': mesh filename '" + filename +
                                "' is not of the form package://PACKAGE/PATH");
                }
                pkg = tail.substr(0, slash);
                rest = tail.substr(slash + 1);
            }
            std::error_code ec;
            fs::path dir = fs::absolute(baseDir.empty() ? fs::path(".") : fs::path(baseDir), ec).lexically_normal();
            // Walk from the URDF's folder up to the file-system root.
            while (true)
            {
                if (isPackage)
                {
                    // the package is a folder next to (or above) the URDF, or the URDF's folder is the package
                    if (found(dir / pkg / rest) || (dir.filename() == pkg && found(dir / rest)))
                    {
                        return absoluteString(tried.back());
                    }
                }
                else if (found(dir / rest))
                {
                    return absoluteString(tried.back());
                }
                const fs::path parent = dir.parent_path();
                if (parent.empty() || parent == dir)
                {
                    break;
                }
                dir = parent;
            }
            if (isPackage)
            {
                // last resort: the path inside the package, relative to the URDF folder (robots shipped with
                // their meshes next to the URDF, package name being the robot's ROS package)
                dir = fs::absolute(baseDir.empty() ? fs::path(".") : fs::path(baseDir), ec).lexically_normal();
                if (found(dir / rest))
                {
                    return absoluteString(tried.back());
                }
            }
        }
        std::string message = "URDF '" + urdfSource + "': mesh '" + filename + "' not found (tried";
        const std::size_t shown = std::min<std::size_t>(tried.size(), 4);
        for (std::size_t i = 0; i < shown; ++i)
        {
            message += (i == 0 ? " " : ", ") + tried[i].string();
        }
        if (tried.size() > shown)
        {
            message += ", ... " + std::to_string(tried.size() - shown) + " more";
        }
        message += ")";
        throw Error(message);
    }
}  // namespace ropras::ompl_ext
