#pragma once
// What each 2D field of a contact study's contact.h5 is, in words: the
// `description` attribute of its dataset (h5py: ds.attrs['description']).
#include <string>

namespace wearscale::studies {

/// The description of the contact.h5 dataset `dataset` ("/fields/pressure",
/// "/stress/depth_2/tau_max"); "" for a dataset it does not know.
std::string contact_field_description(const std::string& dataset);

}  // namespace wearscale::studies
