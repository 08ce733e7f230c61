#include "learning/dqn/GeneralistModel.h"

#include "model/Plan.h"

#include <mutex>
#include <sstream>

namespace fc {

extern const unsigned char kGeneralistModel[];
extern const unsigned long kGeneralistModel_size;

std::shared_ptr<const DqnModel> generalistModel() {
    static std::once_flag once;
    static std::shared_ptr<const DqnModel> model;
    static std::string error;
    std::call_once(once, [] {
        try {
            std::istringstream in(std::string(reinterpret_cast<const char*>(kGeneralistModel),
                                              kGeneralistModel_size));
            auto loaded = std::make_shared<DqnModel>(readDqnModel(in, kGeneralistModelName));
            if (!loaded->info.generalist)
                throw InputError(kGeneralistModelName +
                                 " is a model of one plan, not a generalist");
            model = std::move(loaded);
        } catch (const std::exception& e) {
            error = e.what();
        }
    });
    if (!model)
        throw InputError(error);
    return model;
}

} // namespace fc
