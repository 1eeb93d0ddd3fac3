// A compact, read-only YAML document built from yaml-cpp's parser events (YAML::Parser + YAML::EventHandler), with
// the items of one sequence handed to the caller as they are read and then dropped: a MoveIt scene of 100 000
// objects is read in memory proportional to its largest object, not to the whole document (yaml-cpp's node tree
// took about 0.5 KB per YAML node: 1.4 to 2.5 GB for 100 000 boxes).
#ifndef ROPRAS_OMPL_EXT_SRC_SCENE_YAML_TREE_H
#define ROPRAS_OMPL_EXT_SRC_SCENE_YAML_TREE_H

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ropras::ompl_ext
{
    class YamlTree;

    /// "source:line: where: what" (no line when \a line < 0), the format of every YAML input error
    [[noreturn]] void throwYamlError(const std::string &source, int line, const std::string &where,
                                     const std::string &what);

    /** \brief A node of a YamlTree (a handle: cheap to copy, valid while the tree lives). A missing node
        (a key that a mapping does not have, an index past a sequence's end) is "undefined". */
    class YamlNode
    {
    public:
        YamlNode() = default;

        bool isDefined() const;
        bool isNull() const;
        bool isScalar() const;
        bool isSequence() const;
        bool isMap() const;
        /// an item of the streamed sequence, already handed to the caller (its content is gone)
        bool isReleased() const;

        /// the scalar's text ("" for other nodes)
        std::string_view view() const;
        std::string scalar() const { return std::string(view()); }
        /// the scalar as a number, read as yaml-cpp's as<double>() reads it (".inf", ".nan" too); false for
        /// other text and other nodes
        bool toDouble(double &value) const;

        /// the 0-based line where the node starts (an alias: its anchor's); -1 when undefined
        int line() const;

        /// items of a sequence, entries of a mapping, 0 otherwise
        std::size_t size() const;
        /// item \a i of a sequence (undefined past its end or for other nodes)
        YamlNode operator[](std::size_t i) const;
        /// the value of scalar key \a key of a mapping (undefined when absent or for other nodes)
        YamlNode operator[](std::string_view key) const;

    private:
        friend class YamlTree;
        friend class YamlTreeBuilder;
        YamlNode(const YamlTree *tree, std::size_t index) : tree_(tree), index_(index) {}

        const YamlTree *tree_{nullptr};
        std::size_t index_{0};
    };

    /** \brief One YAML document (the first of the text, as YAML::Load reads it). Malformed YAML and a key given
        twice in one mapping throw ropras::Error "source:line: ...". Aliases share their anchor's node. */
    class YamlTree
    {
    public:
        /// called with each item of the streamed sequence and its index, as soon as the item is complete
        using ItemHandler = std::function<void(const YamlNode &item, std::size_t index)>;

        /** \brief Parses \a text. When \a streamPath is not empty (keys from the root mapping, e.g. {"world",
            "collision_objects"}) and leads through mappings to a sequence, each of its items is passed to
            \a onItem when complete, then dropped from the tree (the sequence keeps a released placeholder). */
        YamlTree(const std::string &text, std::string source, std::vector<std::string> streamPath = {},
                 ItemHandler onItem = {});

        YamlNode root() const { return YamlNode(this, root_); }
        const std::string &source() const { return source_; }

    private:
        friend class YamlNode;
        friend class YamlTreeBuilder;

        enum class Type : unsigned char
        {
            Undefined,
            Null,
            Scalar,
            Sequence,
            Map,
            Released
        };

        struct Node
        {
            Type type;
            int line;
            std::size_t begin;  ///< scalar: offset in text_; container: offset in children_
            std::size_t size;   ///< scalar: length; sequence: items; mapping: 2 x entries (key, value, ...)
        };

        static constexpr std::size_t UNDEFINED = 0;  ///< nodes_[0]
        static constexpr std::size_t RELEASED = 1;   ///< nodes_[1]

        std::string source_;
        std::vector<Node> nodes_;
        std::vector<std::size_t> children_;
        std::string text_;  ///< every scalar's text, one after the other
        std::size_t root_{UNDEFINED};
    };
}  // namespace ropras::ompl_ext

#endif
