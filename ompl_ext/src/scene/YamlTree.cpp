#include "scene/YamlTree.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <charconv>

#include <istream>
#include <memory>
#include <sstream>
#include <streambuf>
#include <unordered_map>

#include "ropras/core/Error.h"

namespace ropras::ompl_ext
{
    void throwYamlError(const std::string &source, int line, const std::string &where, const std::string &what)
    {
        std::ostringstream msg;
        msg << source;
        if (line >= 0)
            msg << ':' << line + 1;
        msg << ": " << where << ": " << what;
        throw Error(msg.str());
    }

    bool YamlNode::isDefined() const
    {
        return tree_ != nullptr && tree_->nodes_[index_].type != YamlTree::Type::Undefined;
    }

    bool YamlNode::isNull() const
    {
        return tree_ != nullptr && tree_->nodes_[index_].type == YamlTree::Type::Null;
    }

    bool YamlNode::isScalar() const
    {
        return tree_ != nullptr && tree_->nodes_[index_].type == YamlTree::Type::Scalar;
    }

    bool YamlNode::isSequence() const
    {
        return tree_ != nullptr && tree_->nodes_[index_].type == YamlTree::Type::Sequence;
    }

    bool YamlNode::isMap() const
    {
        return tree_ != nullptr && tree_->nodes_[index_].type == YamlTree::Type::Map;
    }

    bool YamlNode::isReleased() const
    {
        return tree_ != nullptr && tree_->nodes_[index_].type == YamlTree::Type::Released;
    }

    std::string_view YamlNode::view() const
    {
        if (!isScalar())
            return {};
        const YamlTree::Node &n = tree_->nodes_[index_];
        return std::string_view(tree_->text_).substr(n.begin, n.size);
    }

    namespace
    {
        /// [-]digits[.digits][e[+-]digits] or [-].digits[...]: text that std::from_chars reads as the stream
        /// extraction behind yaml-cpp's as<double>() does (both round correctly)
        bool plainDecimal(std::string_view s)
        {
            std::size_t i = s.size() > 0 && s[0] == '-' ? 1 : 0;
            std::size_t digits = 0;
            const auto skipDigits = [&]
            {
                const std::size_t start = i;
                while (i < s.size() && s[i] >= '0' && s[i] <= '9')
                    ++i;
                return i - start;
            };
            digits += skipDigits();
            if (i < s.size() && s[i] == '.')
            {
                ++i;
                digits += skipDigits();
            }
            if (digits == 0)
                return false;
            if (i < s.size() && (s[i] == 'e' || s[i] == 'E'))
            {
                ++i;
                if (i < s.size() && (s[i] == '+' || s[i] == '-'))
                    ++i;
                if (skipDigits() == 0)
                    return false;
            }
            return i == s.size();
        }
    }  // namespace

    bool YamlNode::toDouble(double &value) const
    {
        if (!isScalar())
            return false;
        const std::string_view text = view();
        if (plainDecimal(text))
        {
            double parsed = 0.0;
            const auto result = std::from_chars(text.data(), text.data() + text.size(), parsed);
            if (result.ec == std::errc() && result.ptr == text.data() + text.size())
            {
                value = parsed;
                return true;
            }
        }
        // anything else (".inf", "+1", "1e400", " 1", "0x10", ...): yaml-cpp's own conversion, whatever it accepts
        return YAML::convert<double>::decode(YAML::Node(std::string(text)), value);
    }

    int YamlNode::line() const
    {
        return tree_ == nullptr ? -1 : tree_->nodes_[index_].line;
    }

    std::size_t YamlNode::size() const
    {
        if (isSequence())
            return tree_->nodes_[index_].size;
        return isMap() ? tree_->nodes_[index_].size / 2 : 0;
    }

    YamlNode YamlNode::operator[](std::size_t i) const
    {
        if (!isSequence())
            return tree_ == nullptr ? YamlNode() : YamlNode(tree_, YamlTree::UNDEFINED);
        const YamlTree::Node &n = tree_->nodes_[index_];
        return YamlNode(tree_, i < n.size ? tree_->children_[n.begin + i] : YamlTree::UNDEFINED);
    }

    YamlNode YamlNode::operator[](std::string_view key) const
    {
        if (!isMap())
            return tree_ == nullptr ? YamlNode() : YamlNode(tree_, YamlTree::UNDEFINED);
        const YamlTree::Node &n = tree_->nodes_[index_];
        for (std::size_t k = 0; k < n.size; k += 2)
        {
            const YamlNode candidate(tree_, tree_->children_[n.begin + k]);
            if (candidate.isScalar() && candidate.view() == key)
                return YamlNode(tree_, tree_->children_[n.begin + k + 1]);
        }
        return YamlNode(tree_, YamlTree::UNDEFINED);
    }

    namespace
    {
        /// reads a string in place (std::istringstream would copy it)
        class StringViewBuffer : public std::streambuf
        {
        public:
            explicit StringViewBuffer(const std::string &text)
            {
                char *begin = const_cast<char *>(text.data());  // only read: the get area is never written
                setg(begin, begin, begin + text.size());
            }
        };
    }  // namespace

    /** \brief Builds a YamlTree from the parser's events: every node is appended to the tree when it starts,
        its children (node indices) are kept on a stack until it ends, then stored together. */
    class YamlTreeBuilder final : public YAML::EventHandler
    {
    public:
        YamlTreeBuilder(YamlTree &tree, const std::vector<std::string> &streamPath, const YamlTree::ItemHandler &onItem)
            : tree_(tree), streamPath_(streamPath), onItem_(onItem)
        {
        }

        void OnDocumentStart(const YAML::Mark &) override {}
        void OnDocumentEnd() override {}

        void OnNull(const YAML::Mark &mark, YAML::anchor_t anchor) override
        {
            const Sizes before = sizes();
            complete(add(YamlTree::Type::Null, mark, 0, 0, anchor), before);
        }

        void OnAlias(const YAML::Mark &, YAML::anchor_t anchor) override
        {
            complete(anchors_.at(anchor), sizes());  // the parser refuses an alias of an unknown anchor
        }

        void OnScalar(const YAML::Mark &mark, const std::string &, YAML::anchor_t anchor,
                      const std::string &value) override
        {
            const Sizes before = sizes();
            const std::size_t begin = tree_.text_.size();
            tree_.text_ += value;
            complete(add(YamlTree::Type::Scalar, mark, begin, value.size(), anchor), before);
        }

        void OnSequenceStart(const YAML::Mark &mark, const std::string &, YAML::anchor_t anchor,
                             YAML::EmitterStyle::value) override
        {
            open(YamlTree::Type::Sequence, mark, anchor);
        }

        void OnSequenceEnd() override { close(); }

        void OnMapStart(const YAML::Mark &mark, const std::string &, YAML::anchor_t anchor,
                        YAML::EmitterStyle::value) override
        {
            open(YamlTree::Type::Map, mark, anchor);
        }

        void OnMapEnd() override { close(); }

    private:
        /// a mapping with more keys than this checks its keys for repeats with a hash table, not one by one
        static constexpr std::size_t LINEAR_KEY_CHECK = 16;

        /// the tree's sizes before a node: dropping a released item restores them
        struct Sizes
        {
            std::size_t nodes, children, text;
        };

        /// a sequence or mapping being read
        struct Open
        {
            std::size_t node;
            std::size_t firstChild;  ///< its children so far: pending_[firstChild...]
            Sizes before;
            /// how many keys of the stream path lead to it (-1: not on the path)
            int onPath;
            /// scalar key -> its 1-based line, for mappings with many keys
            std::unique_ptr<std::unordered_map<std::string, int>> keys;
        };

        Sizes sizes() const { return {tree_.nodes_.size(), tree_.children_.size(), tree_.text_.size()}; }

        std::size_t add(YamlTree::Type type, const YAML::Mark &mark, std::size_t begin, std::size_t size,
                        YAML::anchor_t anchor)
        {
            const std::size_t index = tree_.nodes_.size();
            tree_.nodes_.push_back({type, mark.line, begin, size});
            if (anchor != YAML::NullAnchor)
            {
                if (anchors_.size() <= anchor)
                    anchors_.resize(anchor + 1, YamlTree::UNDEFINED);
                anchors_[anchor] = index;
                anchoredEnd_ = index + 1;
            }
            return index;
        }

        /// the stream-path depth of a container that starts now (-1: off the path)
        int onPath(YamlTree::Type type) const
        {
            const int keys = static_cast<int>(streamPath_.size());
            if (stack_.empty())
                return keys > 0 && type == YamlTree::Type::Map ? 0 : -1;
            const Open &parent = stack_.back();
            const bool isValue = (pending_.size() - parent.firstChild) % 2 == 1;
            if (tree_.nodes_[parent.node].type != YamlTree::Type::Map || parent.onPath < 0 || parent.onPath >= keys ||
                !isValue)
                return -1;
            const YamlNode key(&tree_, pending_.back());
            if (!key.isScalar() || key.view() != streamPath_[static_cast<std::size_t>(parent.onPath)])
                return -1;
            const int depth = parent.onPath + 1;
            const YamlTree::Type wanted = depth < keys ? YamlTree::Type::Map : YamlTree::Type::Sequence;
            return type == wanted ? depth : -1;
        }

        void open(YamlTree::Type type, const YAML::Mark &mark, YAML::anchor_t anchor)
        {
            const Sizes before = sizes();
            const int depth = onPath(type);
            const std::size_t node = add(type, mark, 0, 0, anchor);
            stack_.push_back({node, pending_.size(), before, depth, nullptr});
        }

        void close()
        {
            Open top = std::move(stack_.back());
            stack_.pop_back();
            YamlTree::Node &node = tree_.nodes_[top.node];
            node.begin = tree_.children_.size();
            node.size = pending_.size() - top.firstChild;
            tree_.children_.insert(tree_.children_.end(), pending_.begin() + static_cast<long>(top.firstChild),
                                   pending_.end());
            pending_.resize(top.firstChild);
            complete(top.node, top.before);
        }

        /// a key of \a map that an earlier key of it repeats: "source:line: key 'k': given twice ..."
        void checkKey(Open &map, std::size_t keyNode)
        {
            const YamlNode key(&tree_, keyNode);
            if (!key.isScalar())
                return;
            const std::size_t earlier = (pending_.size() - map.firstChild) / 2;
            int first = -1;
            if (!map.keys && earlier < LINEAR_KEY_CHECK)
            {
                for (std::size_t k = 0; k < earlier && first < 0; ++k)
                {
                    const YamlNode other(&tree_, pending_[map.firstChild + 2 * k]);
                    if (other.isScalar() && other.view() == key.view())
                        first = other.line() + 1;
                }
            }
            else
            {
                if (!map.keys)
                {
                    map.keys = std::make_unique<std::unordered_map<std::string, int>>();
                    for (std::size_t k = 0; k < earlier; ++k)
                    {
                        const YamlNode other(&tree_, pending_[map.firstChild + 2 * k]);
                        if (other.isScalar())
                            map.keys->emplace(other.scalar(), other.line() + 1);
                    }
                }
                const auto [it, fresh] = map.keys->emplace(key.scalar(), key.line() + 1);
                if (!fresh)
                    first = it->second;
            }
            if (first >= 0)
                throwYamlError(tree_.source_, key.line(), "key '" + key.scalar() + "'",
                               "given twice in one mapping (first on line " + std::to_string(first) + ")");
        }

        /// \a node (which started when the tree had the sizes \a before) is complete: hand it to its parent
        void complete(std::size_t node, const Sizes &before)
        {
            if (stack_.empty())
            {
                tree_.root_ = node;
                return;
            }
            Open &parent = stack_.back();
            const YamlTree::Type type = tree_.nodes_[parent.node].type;
            if (type == YamlTree::Type::Map && (pending_.size() - parent.firstChild) % 2 == 0)
                checkKey(parent, node);
            if (type == YamlTree::Type::Sequence && parent.onPath >= 0 &&
                static_cast<std::size_t>(parent.onPath) == streamPath_.size())
            {
                onItem_(YamlNode(&tree_, node), pending_.size() - parent.firstChild);
                if (anchoredEnd_ <= before.nodes)  // nothing later can refer to the item's nodes: drop them
                {
                    tree_.nodes_.resize(before.nodes);
                    tree_.children_.resize(before.children);
                    tree_.text_.resize(before.text);
                }
                pending_.push_back(YamlTree::RELEASED);
                return;
            }
            pending_.push_back(node);
        }

        YamlTree &tree_;
        const std::vector<std::string> &streamPath_;
        const YamlTree::ItemHandler &onItem_;
        std::vector<Open> stack_;
        std::vector<std::size_t> pending_;  ///< children of the open containers, innermost last
        std::vector<std::size_t> anchors_;  ///< anchor -> node
        std::size_t anchoredEnd_{0};        ///< 1 + the largest anchored node
    };

    YamlTree::YamlTree(const std::string &text, std::string source, std::vector<std::string> streamPath,
                       ItemHandler onItem)
        : source_(std::move(source))
    {
        nodes_.push_back({Type::Undefined, -1, 0, 0});  // UNDEFINED
        nodes_.push_back({Type::Released, -1, 0, 0});   // RELEASED
        try
        {
            StringViewBuffer buffer(text);
            std::istream in(&buffer);
            YAML::Parser parser(in);
            YamlTreeBuilder builder(*this, streamPath, onItem);
            parser.HandleNextDocument(builder);
        }
        catch (const YAML::Exception &e)
        {
            throwYamlError(source_, e.mark.line, "malformed YAML", e.msg);
        }
        if (root_ == UNDEFINED)  // an empty document is a null node, as YAML::Load reads it
        {
            root_ = nodes_.size();
            nodes_.push_back({Type::Null, -1, 0, 0});
        }
        nodes_.shrink_to_fit();
        children_.shrink_to_fit();
        text_.shrink_to_fit();
    }
}  // namespace ropras::ompl_ext
