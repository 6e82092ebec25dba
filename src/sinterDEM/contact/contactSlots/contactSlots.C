// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactSlots.H"
#include "error.H"
#include "transform.H"

namespace
{

Foam::label addSlot
(
    Foam::DynamicList<Foam::contactSlots::slot>& slots,
    Foam::label& stride,
    const Foam::word& name,
    const Foam::word& owner,
    const bool isVector,
    const bool odd
)
{
    for (const Foam::contactSlots::slot& s : slots)
    {
        if (s.name == name)
        {
            FatalErrorInFunction
                << "Per-contact slot " << name << " of " << owner
                << " is already declared by " << s.owner
                << Foam::exit(Foam::FatalError);
        }
    }
    const Foam::label offset = stride;
    slots.append({name, owner, offset, isVector, odd});
    stride += isVector ? 3 : 1;
    return offset;
}

} // End anonymous namespace


Foam::label Foam::contactSlots::addScalar
(
    const word& name,
    const word& owner,
    const bool odd
)
{
    return addSlot(slots_, stride_, name, owner, false, odd);
}


Foam::label Foam::contactSlots::addVector
(
    const word& name,
    const word& owner,
    const bool odd
)
{
    vectorOffsets_.append(stride_);
    return addSlot(slots_, stride_, name, owner, true, odd);
}


Foam::word Foam::contactSlots::fieldName(const slot& s)
{
    word n(s.name);
    if (n.size())
    {
        n[0] = toupper(n[0]);
    }
    return "demContact" + n;
}


void Foam::contactSlots::flipSides(scalar* block) const
{
    for (const slot& s : slots_)
    {
        if (s.odd)
        {
            for (label c = 0; c < s.size(); ++c)
            {
                block[s.offset + c] = -block[s.offset + c];
            }
        }
    }
}


void Foam::contactSlots::transform(const tensor& T, scalar* block) const
{
    for (const slot& s : slots_)
    {
        if (s.isVector)
        {
            scalar* v = block + s.offset;
            const vector r = Foam::transform(T, vector(v[0], v[1], v[2]));
            v[0] = r.x();
            v[1] = r.y();
            v[2] = r.z();
        }
    }
}
