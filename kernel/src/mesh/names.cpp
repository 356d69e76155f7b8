#include "nome/mesh/names.hpp"

namespace nome {

const std::vector<std::string>& Names::list() const {
  static const std::vector<std::string> none;
  return list_ ? *list_ : none;
}

std::vector<std::string>& Names::writable() {
  if (!list_)
    list_ = std::make_shared<std::vector<std::string>>();
  else if (list_.use_count() > 1)
    list_ = std::make_shared<std::vector<std::string>>(*list_);
  return *list_;
}

}  // namespace nome
