#include "ropras/scenarios/ViewerPage.h"

#include "SvgPicture.h"

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/scenarios/ScenarioRegistry.h"

namespace ropras::scenarios
{
    namespace
    {
        std::string readThreeFile(const std::string &dir, const std::string &name)
        {
            const std::string path = dir + "/" + name;
            try
            {
                return readInputFile(path, "three.js");
            }
            catch (const Error &e)
            {
                throw Error(std::string(e.what()) +
                            " (`ropras view` embeds three.js from Debian's libjs-three: apt-get install libjs-three, "
                            "or give --three DIR)");
            }
        }

        void replaceOnce(std::string &page, const std::string &key, const std::string &value)
        {
            const auto at = page.find(key);
            if (at == std::string::npos)
            {
                throw Error("viewer page template: placeholder " + key + " is missing");
            }
            page.replace(at, key.size(), value);
        }
    }  // namespace

    std::string scriptSafe(const std::string &text)
    {
        std::string out;
        out.reserve(text.size());
        for (std::size_t i = 0; i < text.size(); ++i)
        {
            out += text[i];
            if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/')
            {
                out += '\\';
            }
        }
        return out;
    }

    ThreeJs loadThreeJs(const std::string &dir)
    {
        ThreeJs three;
        three.library = readThreeFile(dir, "three.min.js");
        three.orbitControls = readThreeFile(dir, "examples/js/controls/OrbitControls.js");
        return three;
    }

    std::string viewerPage(const nlohmann::json &view, const ThreeJs &three)
    {
        std::string page = embeddedFile("common/viewer/viewer.html");
        const std::string title = view.contains("title") && view["title"].is_string() ? view["title"].get<std::string>()
                                                                                      : std::string("ropras view");
        // the script parts go in last, so that no placeholder text inside them is ever replaced
        replaceOnce(page, "@ROPRAS_TITLE@", detail::xmlEscape(title));
        replaceOnce(page, "@ROPRAS_DATA@",
                    scriptSafe(view.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
        replaceOnce(page, "/*@ROPRAS_VIEWER@*/", scriptSafe(embeddedFile("common/viewer/viewer.js")));
        replaceOnce(page, "/*@ROPRAS_ORBIT@*/", scriptSafe(three.orbitControls));
        replaceOnce(page, "/*@ROPRAS_THREE@*/", scriptSafe(three.library));
        return page;
    }
}  // namespace ropras::scenarios
