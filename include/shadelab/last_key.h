// What a kept value (a label's image, a panel's text) was last made from: its key, the values it shows.
// changed() says whether the value must be made again, and remembers the new key; a frame that shows the
// same values as the last then makes nothing.
#pragma once

#include <optional>

namespace shadelab {

template <class Key> class LastKey {
public:
    bool changed(const Key& key) {
        if (key_ && *key_ == key) return false;
        key_ = key;
        return true;
    }
    // The value could not be made for the key changed() took: the next call says changed again.
    void forget() { key_.reset(); }

private:
    std::optional<Key> key_;
};

} // namespace shadelab
